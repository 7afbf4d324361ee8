#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora (tests/fuzz/corpus/<target>/) from the repository's own data: the
shipped scenes, the buoy model and the sand texture, small glTF models like the unit tests' own, .npy files
of every header version, and demo scripts. The corpora are committed so that `make test` needs neither
Python nor a C++ compiler for them; run this again (it needs c++, libstb-dev and libwebp-dev for the JPEG and WebP) when an input
format changes."""
import json, os, shutil, struct, subprocess, tempfile, zlib

root = os.path.dirname(os.path.abspath(__file__))
repo = os.path.normpath(os.path.join(root, "..", ".."))
corpus = os.path.join(root, "corpus")


def put(target, name, data):
    os.makedirs(os.path.join(corpus, target), exist_ok=True)
    with open(os.path.join(corpus, target, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def read(*parts):
    return open(os.path.join(repo, *parts), "rb").read()


for target in ("scene", "gltf", "image", "npy", "demo_script"):
    shutil.rmtree(os.path.join(corpus, target), ignore_errors=True)

# ---- scene: the file's text, then the --set overrides, each after a 0xff byte (fuzz_scene.cpp) ----------
for s in ("default", "open-ocean", "tropical-lagoon", "harbour"):
    put("scene", s + ".json", read("scenes", s + ".json"))
put("scene", "overrides", read("scenes", "default.json") +
    b"\xffocean.spectrum.type=pm\xffcamera.fov_deg=40\xffocean.cascades=[{\"patch_size_m\":100,\"resolution\":64}]")
put("scene", "minimal.json", "{}")
# An empty file part: the path of commands whose --scene is optional (all defaults plus the overrides).
put("scene", "no-scene", b"\xffsun.elevation_deg=10\xffwater.type=jerlov-3C\xffobjects=[{\"file\":\"a.glb\"}]")
# Every field of docs/scene-format.md with a legal value other than its default.
every_field = {
    "camera": {"position": [1, 2, 3], "yaw_deg": 30, "pitch_deg": -10, "fov_deg": 40, "near_m": 0.5,
               "far_m": 900},
    "sun": {"elevation_deg": -5, "azimuth_deg": 90, "intensity": 2},
    "ocean": {"seed": 4294967295, "depth_m": 20, "choppiness": 0, "loop_period_s": 60,
              "spectrum": {"type": "phillips", "wind_speed_mps": 12, "wind_direction_deg": 300, "fetch_km": 50,
                           "gamma": 2, "spreading": "donelan-banner", "swell": 1, "small_wave_cutoff_m": 0.1},
              "cascades": [{"patch_size_m": 500, "resolution": 1024}, {"patch_size_m": 7, "resolution": 64}],
              "foam": {"threshold": -1, "decay_per_s": 0}},
    "water": {"type": "custom", "table": "tables/water.csv", "bottom_albedo": 1, "phase": "constant",
              "phase_x1": 2.5, "lut_gamma": 0.05, "ior": 1.5, "lut_size": 2, "lut_r_max_m": 10000,
              "lut_h_max_m": 1000},
    "seafloor": {"type": "gltf", "file": "floor.glb", "texture": "", "albedo": [0, 0.5, 1]},
    "objects": [{"name": "rock", "file": "rock.gltf", "position": [0, -3, 9], "rotation_deg": [360, -90, 45],
                 "scale": 1000}],
    "lights": [{"position": [0, 1, 0], "colour": [100, 0, 0], "intensity": 1000000, "range_m": 100000}],
    "render": {"width": 16, "height": 8192, "exposure": 0.01, "gamma": 3, "tone_map": "clamp",
               "effects": {"reflection": False, "refraction": False, "foam": False}},
    "time_s": 86400,
}
put("scene", "every-field.json", json.dumps(every_field, indent=1))


# ---- image: PNG and JPEG bytes (fuzz_image.cpp) ------------------------------------------------------------
def png(w, h, colour_type, rows, depth=8, extra=b""):
    raw = b"".join(b"\0" + rows(y) for y in range(h))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, colour_type, 0, 0, 0)) +
            (chunk(b"PLTE", extra) if extra else b"") + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


put("image", "rgba4x3.png", png(4, 3, 6, lambda y: bytes((x * 60, y * 80, 128, 255)[c] for x in range(4) for c in range(4))))
put("image", "rgb8x8.png", png(8, 8, 2, lambda y: bytes((x * 30 + y) % 256 for x in range(8) for c in range(3))))
put("image", "grey16x1.png", png(16, 1, 0, lambda y: bytes(range(0, 256, 16))))
put("image", "grey-alpha16bit2x2.png", png(2, 2, 4, lambda y: bytes(range(y * 8, y * 8 + 8)), depth=16))
put("image", "palette4x2.png", png(4, 2, 3, lambda y: bytes((x + y) % 3 for x in range(4)), extra=bytes(range(9))))

# A 16x16 crop of the shipped sand texture, as PNG and JPEG (stb's encoder) and as lossless and lossy WebP
# (libwebp's encoder).
crop_cpp = r"""
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
#include <webp/encode.h>
#include <cstdio>
static bool write_all(const char* path, const unsigned char* data, size_t size) {
  FILE* f = std::fopen(path, "wb");
  bool ok = f && size > 0 && std::fwrite(data, 1, size, f) == size;
  if (f) std::fclose(f);
  WebPFree(const_cast<unsigned char*>(data));
  return ok;
}
int main(int, char** argv) {
  int w, h, n;
  unsigned char* p = stbi_load(argv[1], &w, &h, &n, 3);
  if (!p || w < 16 || h < 16) return 1;
  static unsigned char crop[16 * 16 * 3];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16 * 3; ++x) crop[y * 48 + x] = p[y * w * 3 + x];
  unsigned char *lossless = nullptr, *lossy = nullptr;
  const size_t n_lossless = WebPEncodeLosslessRGB(crop, 16, 16, 48, &lossless);
  const size_t n_lossy = WebPEncodeRGB(crop, 16, 16, 48, 80.0f, &lossy);
  return !(stbi_write_png(argv[2], 16, 16, 3, crop, 48) && stbi_write_jpg(argv[3], 16, 16, 3, crop, 90) &&
           write_all(argv[4], lossless, n_lossless) && write_all(argv[5], lossy, n_lossy));
}
"""
with tempfile.TemporaryDirectory() as tmp:
    src, exe = os.path.join(tmp, "crop.cpp"), os.path.join(tmp, "crop")
    open(src, "w").write(crop_cpp)
    subprocess.run(["c++", "-O1", "-I/usr/include/stb", src, "-o", exe, "-lwebp"], check=True)
    outputs = ["sand16.png", "sand16.jpg", "sand16-lossless.webp", "sand16-lossy.webp"]
    subprocess.run([exe, os.path.join(repo, "scenes", "assets", "sand.png")] + [os.path.join(tmp, o) for o in outputs],
                   check=True)
    sand = {o: open(os.path.join(tmp, o), "rb").read() for o in outputs}
for name, data in sand.items():
    put("image", name, data)
sand_png, sand_jpg = sand["sand16.png"], sand["sand16.jpg"]


# ---- gltf: byte 0 even = a .glb, odd = a .gltf whose text ends at the first NUL and "m.bin" follows --------
def glb(doc, bin_data):
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    bin_data += b"\0" * (-len(bin_data) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(bin_data), 0x004E4942) + bin_data
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


class Model:
    """A glTF document and its one buffer, as the unit tests' Builder (tests/unit/gltf/gltf_test.cpp) makes them."""

    def __init__(self):
        self.doc, self.bin = {"asset": {"version": "2.0"}}, b""

    def push(self, array, value):
        self.doc.setdefault(array, []).append(value)
        return len(self.doc[array]) - 1

    def view(self, data):
        self.bin += b"\0" * (-len(self.bin) % 4)
        v = self.push("bufferViews", {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return v

    def accessor(self, fmt, values, component, count, kind, **extra):
        return self.push("accessors", dict({"bufferView": self.view(struct.pack(fmt, *values)),
                                            "componentType": component, "count": count, "type": kind}, **extra))

    def write(self, name):
        doc = dict(self.doc, buffers=[{"byteLength": len(self.bin)}])
        put("gltf", name + ".glb", b"\0" + glb(doc, self.bin))
        doc["buffers"][0]["uri"] = "m.bin"
        put("gltf", name + ".gltf", b"\1" + json.dumps(doc).encode() + b"\0" + self.bin)


FLOAT, USHORT, UBYTE = 5126, 5123, 5121

tri = Model()
pos = tri.accessor("<9f", (0, 0, 0, 1, 0, 0, 0, 1, 0), FLOAT, 3, "VEC3", min=[0, 0, 0], max=[1, 1, 0])
idx = tri.accessor("<3H", (0, 1, 2), USHORT, 3, "SCALAR")
tri.push("meshes", {"primitives": [{"attributes": {"POSITION": pos}, "indices": idx}]})
tri.push("nodes", {"mesh": 0})
tri.doc.update(scene=0, scenes=[{"nodes": [0]}])
tri.write("triangle")

# The unit quad with normals, UVs, a material and the sand crop as its base colour (PNG; JPEG in the .glb).
for name, image, mime in (("quad-png", sand_png, "image/png"), ("quad-jpeg", sand_jpg, "image/jpeg")):
    q = Model()
    pos = q.accessor("<12f", (0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0), FLOAT, 4, "VEC3")
    nrm = q.accessor("<12f", (0, 0, 1) * 4, FLOAT, 4, "VEC3")
    uv = q.accessor("<8B", (0, 255, 255, 255, 255, 0, 0, 0), UBYTE, 4, "VEC2", normalized=True)
    idx = q.accessor("<6H", (0, 1, 2, 0, 2, 3), USHORT, 6, "SCALAR")
    q.push("meshes", {"name": "quad", "primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv},
                                                      "indices": idx, "material": 0, "mode": 4}]})
    q.push("images", {"bufferView": q.view(image), "mimeType": mime, "name": "sand"})
    q.push("textures", {"source": 0})
    q.push("materials", {"name": "sand", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 1, 1, 1],
                                                                  "baseColorTexture": {"index": 0}}})
    q.push("nodes", {"mesh": 0})
    q.doc["scenes"] = [{"nodes": [0]}]
    q.write(name)

# Every material slot of issue 17 on a quantized quad: SHORT positions and BYTE normals and tangents
# (KHR_mesh_quantization), two texture sets, a sampler, KHR_texture_transform, emissive strength, MASK.
SHORT, BYTE = 5122, 5120
p = Model()
pos = p.accessor("<16h", (0, 0, 0, 0, 100, 0, 0, 0, 100, 100, 0, 0, 0, 100, 0, 0), SHORT, 4, "VEC3",
                 min=[0, 0, 0], max=[100, 100, 0])
p.doc["bufferViews"][p.doc["accessors"][pos]["bufferView"]]["byteStride"] = 8
nrm = p.accessor("<16b", (0, 0, 127, 0) * 4, BYTE, 4, "VEC3", normalized=True)
p.doc["bufferViews"][p.doc["accessors"][nrm]["bufferView"]]["byteStride"] = 4
tan = p.accessor("<16b", (127, 0, 0, 127) * 4, BYTE, 4, "VEC4", normalized=True)
uv0 = p.accessor("<8B", (0, 255, 255, 255, 255, 0, 0, 0), UBYTE, 4, "VEC2", normalized=True)
uv1 = p.accessor("<8f", (0, 0, 1, 0, 1, 1, 0, 1), FLOAT, 4, "VEC2")
idx = p.accessor("<6H", (0, 1, 2, 0, 2, 3), USHORT, 6, "SCALAR")
p.push("meshes", {"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TANGENT": tan, "TEXCOORD_0": uv0,
                                                 "TEXCOORD_1": uv1}, "indices": idx, "material": 0}]})
p.push("images", {"bufferView": p.view(sand_png), "mimeType": "image/png"})
p.push("samplers", {"magFilter": 9728, "minFilter": 9985, "wrapS": 33648, "wrapT": 33071})
p.push("textures", {"source": 0, "sampler": 0})
transform = {"KHR_texture_transform": {"offset": [0.5, 0], "rotation": 0.5, "scale": [2, 2], "texCoord": 1}}
p.push("materials", {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions": transform},
                                              "metallicRoughnessTexture": {"index": 0, "texCoord": 1},
                                              "metallicFactor": 0.5, "roughnessFactor": 0.25},
                     "normalTexture": {"index": 0, "scale": 0.8}, "occlusionTexture": {"index": 0, "strength": 0.5},
                     "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 0.5, 0],
                     "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 3}},
                     "alphaMode": "MASK", "alphaCutoff": 0.4, "doubleSided": True})
p.push("nodes", {"mesh": 0, "scale": [0.01, 0.01, 0.01]})
p.doc.update(scene=0, scenes=[{"nodes": [0]}],
             extensionsUsed=["KHR_mesh_quantization", "KHR_texture_transform", "KHR_materials_emissive_strength"],
             extensionsRequired=["KHR_mesh_quantization"])
p.write("pbr-quantized")

# A node hierarchy (matrix, TRS), a triangle strip and a sparse accessor, with an unsupported extension.
h = Model()
pos = h.accessor("<12f", (0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0), FLOAT, 4, "VEC3")
sparse_idx, sparse_val = h.view(struct.pack("<H", 3) + b"\0\0"), h.view(struct.pack("<3f", 2, 2, 0))
h.doc["accessors"][pos]["sparse"] = {"count": 1, "indices": {"bufferView": sparse_idx, "componentType": USHORT},
                                     "values": {"bufferView": sparse_val}}
h.push("meshes", {"primitives": [{"attributes": {"POSITION": pos}, "mode": 5}]})
h.push("nodes", {"children": [1, 2], "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]})
h.push("nodes", {"mesh": 0, "translation": [0, 1, 0], "rotation": [0, 0.7071068, 0, 0.7071068], "scale": [2, 2, 2]})
h.push("nodes", {"mesh": 0, "extensions": {"KHR_lights_punctual": {"light": 0}}})
h.doc.update(scene=0, scenes=[{"nodes": [0]}], extensionsUsed=["KHR_lights_punctual"])
h.write("hierarchy")

# The shipped buoy (the boat adds nothing but size).
doc = json.loads(read("scenes", "assets", "buoy.gltf"))
data = read("scenes", "assets", "buoy.bin")
doc["buffers"][0]["uri"] = "m.bin"
put("gltf", "buoy.gltf", b"\1" + json.dumps(doc).encode() + b"\0" + data)
del doc["buffers"][0]["uri"]
put("gltf", "buoy.glb", b"\0" + glb(doc, data))


# ---- npy: float32 arrays in versions 1.0, 2.0 and 3.0 ------------------------------------------------------
def npy(shape, values, major=1, descr="<f4"):
    shape_text = "(" + ", ".join(str(d) for d in shape) + ("," if len(shape) == 1 else "") + ")"
    header = "{'descr': '%s', 'fortran_order': False, 'shape': %s, }" % (descr, shape_text)
    prefix_len = 10 if major == 1 else 12
    header += " " * (-(prefix_len + len(header) + 1) % 64) + "\n"
    size = struct.pack("<H", len(header)) if major == 1 else struct.pack("<I", len(header))
    return b"\x93NUMPY" + bytes((major, 0)) + size + header.encode() + struct.pack("<%df" % len(values), *values)


put("npy", "scalar.npy", npy((), [1.5]))
put("npy", "vector.npy", npy((3,), [1, -2, 3.25]))
put("npy", "cube_v2.npy", npy((2, 2, 2), [float(i) for i in range(8)], 2))
put("npy", "empty_v3.npy", npy((0, 4), [], 3))
put("npy", "special-values.npy", npy((2, 3), [float("nan"), float("inf"), -float("inf"), -0.0, 1e-45, 3.4e38]))

# ---- demo_script: the forms docs/demo.md shows ---------------------------------------------------------------
put("demo_script", "basic.txt", "# comment\n0 sun.elevation_deg=20\n10 camera.fov_deg=40\n")
put("demo_script", "window.txt", "5\twindow.size=640x360\r\n7 ocean.cascades=[{\"patch_size_m\":100,\"resolution\":64}]\n")
