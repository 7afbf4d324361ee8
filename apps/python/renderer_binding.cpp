// lagoon.Renderer: a Vulkan context and render::OceanRenderer for one scene; render() returns the frame as
// numpy, the same frame `lagoon render` writes (the same renderer, the same scene checks).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "dataset/frame_metadata.h"
#include "dataset/ground_truth.h"
#include "render/cold_compile.h"
#include "render/ocean_renderer.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "vk/context.h"
#include "world_binding.h"

namespace lagoon::python {
namespace {

class Renderer {
 public:
  Renderer(const scene::Scene& scene, const std::optional<std::string>& device, const World* world)
      : scene_(scene) {
    world::VehicleTracks tracks;
    if (world) {
      if (world->scene().vehicles.size() != scene_.vehicles.size())
        throw py::value_error("world= steps a scene with " + std::to_string(world->scene().vehicles.size()) +
                              " vehicles, this scene has " + std::to_string(scene_.vehicles.size()) +
                              ": give the Renderer the World's scene (or one with the same vehicles[])");
      tracks = world->tracks();
    }
    vk::ContextOptions options = vk::ContextOptions::from_environment();
    if (device) options.device_override = *device;
    auto ctx = vk::Context::create(options);
    if (!ctx) throw std::runtime_error(ctx.error().message);
    ctx_ = std::move(ctx).value();
    // A first render of this build on a CPU device compiles the frame on a second one too.
    cold_ = render::ColdCompile::start_if_cold(*ctx_, options, scene_);
    auto renderer = render::OceanRenderer::create(*ctx_, scene_, tracks);
    if (!renderer) throw std::runtime_error(renderer.error().message);
    renderer_ = std::move(renderer).value();
  }

  // The frame at `time` (default: the scene's time_s) seen from `camera` (default: the scene's; a dict of
  // scene.camera's fields, checked as the scene file's are): {"image": H x W x 3 uint8, "metadata": dict,
  // <aov>: float32 ...}.
  py::dict render(std::optional<double> time, const std::optional<py::dict>& camera,
                  const std::vector<std::string>& aovs) {
    for (const std::string& name : aovs)
      if (!dataset::find_aov(name))
        throw py::value_error("no AOV named '" + name + "'; the AOVs are " + dataset::aov_names() +
                              " (docs/datasets.md)");
    scene::Scene frame = scene_;
    if (camera) frame = with_camera(*camera);
    if (time) {
      check_time_bounds(*time, "render(time=...)");
      check_body_cost(renderer_->body_hull_seconds_to(*time), *time, "render(time=...)");
      frame.time_s = float(*time);
    }
    io::Image8 image;
    dataset::GroundTruth gt;
    {
      py::gil_scoped_release unlocked;  // other Python threads run while the device renders
      image = renderer_->render(frame);
      cold_failures_ += render::ColdCompile::finish(cold_, *ctx_);  // after the first frame only
      if (!aovs.empty())
        gt = dataset::frame_ground_truth(
            *renderer_, frame, std::any_of(aovs.begin(), aovs.end(), dataset::GroundTruth::needs_terms));
    }
    py::dict out;
    py::array_t<uint8_t> colour({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
    uint8_t* dst = colour.mutable_data();
    // RGBA to RGB: the one copy of the frame, so the image is contiguous (as OpenCV and PIL want it).
    const uint8_t* src = image.rgba.data();
    for (size_t i = 0, n = size_t(image.width) * image.height; i < n; ++i, dst += 3, src += 4) {
      dst[0] = src[0];
      dst[1] = src[1];
      dst[2] = src[2];
    }
    out["image"] = colour;
    // The dataset's frame JSON less what names its files (there are none) and its index in a sequence.
    nlohmann::ordered_json metadata = dataset::frame_metadata(frame, 0, {});
    for (const char* key : {"frame", "image", "aov"}) metadata.erase(key);
    out["metadata"] = to_python(metadata);
    // The AOVs are handed over, not copied: the arrays view the ground truth's planes, which a capsule keeps
    // alive for as long as any of them is.
    auto owner = std::make_unique<dataset::GroundTruth>(std::move(gt));
    const dataset::GroundTruth& planes = *owner;
    py::capsule keep(owner.release(), [](void* p) { delete static_cast<dataset::GroundTruth*>(p); });
    for (const std::string& name : aovs) {
      const std::vector<float>& values = planes.plane(name);
      const size_t pixels = size_t(planes.width) * planes.height;
      std::vector<py::ssize_t> shape{py::ssize_t(planes.height), py::ssize_t(planes.width)};
      if (values.size() == 3 * pixels) shape.push_back(3);  // as the dataset's .npy files
      out[py::str(name)] = py::array_t<float>(shape, values.data(), keep);
    }
    return out;
  }

  py::dict device() const {
    const vk::DeviceInfo& info = ctx_->device_info();
    py::dict d;
    d["name"] = info.name;
    d["type"] = info.type;
    d["driver"] = info.driver_name;
    d["driver_version"] = info.driver_version;
    return d;
  }

  const scene::Scene& scene() const { return scene_; }

  // Every device Vulkan offered, in LAGOON_DEVICE's order, with which is in use and why any is unusable.
  py::list devices() const {
    py::list out;
    const std::vector<vk::DeviceCandidate>& all = ctx_->device_candidates();
    for (size_t i = 0; i < all.size(); ++i) {
      py::dict d;
      d["index"] = i;
      d["name"] = all[i].name;
      d["type"] = vk::device_type_name(all[i].type);
      d["usable"] = all[i].unsuitable_reason.empty();
      d["why_not"] = all[i].unsuitable_reason;
      d["in_use"] = i == ctx_->device_info().index;
      out.append(d);
    }
    return out;
  }
  uint32_t validation_errors() const { return ctx_->validation().failures() + cold_failures_; }

 private:
  scene::Scene with_camera(const py::dict& camera) const {
    nlohmann::ordered_json doc = scene::scene_to_json(scene_, std::filesystem::current_path());
    nlohmann::json fields = from_python(camera);
    if (!fields.is_object()) throw py::type_error("camera must be a dict of scene.camera's fields");
    doc["camera"] = nlohmann::ordered_json(fields);
    auto scene = scene::parse_scene(nlohmann::json(doc), "render(camera=...)");
    if (!scene) {
      raise_scene_error(scene.error().message);
    }
    return *scene;
  }

  scene::Scene scene_;
  std::unique_ptr<vk::Context> ctx_;
  std::unique_ptr<render::OceanRenderer> renderer_;
  // Last, so that it is waited for first.
  std::unique_ptr<render::ColdCompile> cold_;
  uint32_t cold_failures_ = 0;  // the second device's validation errors (it drew the same frame)
};

}  // namespace

void bind_renderer(py::module_& m) {
  py::class_<Renderer>(m, "Renderer", "Renders one scene's frames on a Vulkan device.")
      .def(py::init<const scene::Scene&, const std::optional<std::string>&, const World*>(), py::arg("scene"),
           py::arg("device") = py::none(), py::arg("world") = nullptr,
           "Opens the device (None: as LAGOON_DEVICE or the automatic choice; else an index or a name "
           "substring) and builds the renderer; raises RuntimeError with the reason when it cannot. With "
           "`world` (a World of the same scene) the vehicles follow that world's tracks: what its helm() and "
           "set_pose() order is what the frames show.")
      .def("render", &Renderer::render, py::arg("time") = py::none(), py::arg("camera") = py::none(),
           py::arg("aovs") = std::vector<std::string>{},
           "The frame as a dict: 'image', an H x W x 3 uint8 array (sRGB, tone-mapped: the PNG `lagoon "
           "render` writes), 'metadata' (intrinsics K, poses in world, ENU and NED, the sun, the water; "
           "the JSON a sequence writes beside each frame), and each of `aovs` (depth, normal, water_mask, "
           "object_id, clean, "
           "transmission, backscatter; docs/datasets.md) as float32, H x W or H x W x 3, the arrays "
           "`lagoon render --aov` writes. `time` in s (default the scene's time_s); `camera` a dict such "
           "as {'position': [0, 3, -10], 'look_at': [0, 0, 20], 'fov_deg': 55}. The GIL is released while "
           "the device renders.")
      .def_property_readonly("device", &Renderer::device, "The device in use: name, type, driver.")
      .def_property_readonly("scene", &Renderer::scene)
      .def("devices", &Renderer::devices,
           "Every Vulkan device, as LAGOON_DEVICE and `device=` count them: index, name, type, usable, "
           "why_not (what it lacks), in_use.")
      .def_property_readonly(
          "validation_errors", &Renderer::validation_errors,
          "How many errors the Vulkan validation layer reported so far (LAGOON_VALIDATION=1 "
          "turns it on; 0 without it).");
}

}  // namespace lagoon::python
