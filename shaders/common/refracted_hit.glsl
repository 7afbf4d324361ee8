// Where the refracted ray from a point of the water surface meets the floor or a submerged object (issue 39):
// the refraction pass drew them from the camera into `refraction_depth`, so a point q along the ray can be
// looked up by projecting it onto the screen. The search is a fixed point on the depth below the surface:
// guess how far along the ray the hit is (first from what the pixel itself sees), project, read the point
// drawn there, and take its depth below the surface point for the next guess. A level floor is exact after
// the first step and an object's level top after the second. The point is where a ray trace through the displaced surface puts it, not
// a flat screen offset. It follows what is drawn, so without a floor a submerged object is found only
// where the pixel's own line of sight already meets it. The fixed point can settle on floor behind an object
// the ray meets first (it jumps to whatever the pixel sees, past the object): the ray between the water and
// that hit is therefore sampled on the screen, and a shallower level drawn along it (an object's top, its
// nearer side) restarts the search from above, which settles on the first thing the ray meets. Needs
// `frame`, `refraction_depth`, `refraction_albedo` (its alpha tells objects from the procedural floor,
// shared/mesh.h) and the fragment's depth (gl_FragCoord.z) to reject what stands in front of the water.

const int kRefractedSteps = 4;
// Samples of the ray above the first hit found, one per kSamplePixels of its image on the screen and at most
// kFirstHitSamples: they find a 1 m tile 2-8 m down above a 12 m floor to within a pixel at 640 x 360
// (tests/render/refraction_render_test.cpp). An object narrower on the screen than the samples' spacing can
// be missed; where the ray's image is short (far water, shallow floor), so is the search.
const int kFirstHitSamples = 6;
const float kSamplePixels = 8.0;
const int kRestartSteps = 4;
layout(constant_id = LAGOON_SURFACE_SPEC_FIRST_HIT) const bool kFirstHitSearch = true;

vec3 world_of(vec2 uv, float depth) {
  vec4 c = frame.inv_view_proj * vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
  return c.xyz / c.w;
}

// The texel of the refraction pass's targets at `uv`, the one a nearest lookup of its depth reads.
ivec2 refraction_texel(vec2 uv) { return ivec2(min(uv * frame.screen.xy, frame.screen.xy - 1.0)); }

// world_of(uv, depth).y alone: two rows of the inverse instead of four.
float world_y_of(vec2 uv, float depth) {
  vec4 ndc = vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
  mat4 m = frame.inv_view_proj;
  return dot(vec4(m[0].y, m[1].y, m[2].y, m[3].y), ndc) / dot(vec4(m[0].w, m[1].w, m[2].w, m[3].w), ndc);
}

// The refracted ray on the screen: its clip position is linear along the ray, so p's and t's are projected once
// and each point is a multiply-add. The projection is the inverse's inverse: reading frame.view_proj in this
// fragment shader makes lavapipe's resident memory grow by about 0.9 MiB a frame (Mesa 22.3; `lagoon soak`
// +32 % in 100 frames), this does not.
struct ScreenRay {
  vec4 clip_p, clip_t;
  float down, max_m;
};

// The screen position of the point `s` metres along the ray. Off the screen nothing was drawn: the edge's
// nearest pixel stands in (a level floor continues there).
vec2 screen_at(ScreenRay r, float s) {
  vec4 clip = r.clip_p + s * r.clip_t;
  return clamp(vec2(0.5, 0.5) + vec2(0.5, -0.5) * clip.xy / clip.w, vec2(0.0), vec2(1.0));
}

// The fixed point from what the pixel itself sees. The steps stop when a guess reads back the depth it came
// from. When they do not settle, the ray passes behind an object as the camera sees it, to floor the object
// hides; the deepest point found (floor beside the object) stands in for it, not the object. Where the ray
// meets something in front of the water, the last point found (at first the pixel's own). `below`: the depth
// below the surface point of what is returned.
vec2 hit_from_the_pixel(vec3 p, ScreenRay r, out float depth, out float below) {
  vec2 uv = gl_FragCoord.xy * frame.screen.zw;
  depth = textureLod(refraction_depth, uv, 0.0).r;
  below = p.y - world_y_of(uv, depth);
  float last = -1.0;
  vec2 deepest_uv = uv;
  float deepest_depth = depth, deepest = below;
  for (int i = 0; i < kRefractedSteps; ++i) {
    float s = clamp(below / r.down, 0.0, r.max_m);
    if (abs(s - last) < 0.01 + 0.01 * s) return uv;  // the guess reads back its own depth: settled
    last = s;
    vec2 next = screen_at(r, s);
    float d = textureLod(refraction_depth, next, 0.0).r;
    if (d < gl_FragCoord.z) return uv;
    uv = next;
    depth = d;
    below = p.y - world_y_of(uv, depth);
    if (below > deepest) {
      deepest = below;
      deepest_uv = uv;
      deepest_depth = depth;
    }
  }
  if (abs(clamp(below / r.down, 0.0, r.max_m) - last) < 0.01 + 0.01 * last) return uv;
  depth = deepest_depth;
  below = deepest;
  return deepest_uv;
}

// The fixed point again, from the level `level` below the surface point: true when it settles, with the hit.
bool hit_from_level(vec3 p, ScreenRay r, float level, out vec2 uv, out float depth, out float below) {
  float s = clamp(level / r.down, 0.0, r.max_m);
  for (int i = 0; i < kRestartSteps; ++i) {
    uv = screen_at(r, s);
    depth = textureLod(refraction_depth, uv, 0.0).r;
    if (depth < gl_FragCoord.z) return false;
    below = p.y - world_y_of(uv, depth);
    float next = clamp(below / r.down, 0.0, r.max_m);
    if (abs(next - s) < 0.01 + 0.01 * s) return true;
    s = next;
  }
  return false;
}

// `p`: the surface point; `t`: the refracted direction (unit, downward); `max_m`: the longest path worth
// following (the LUT's depth along the ray). Returns the screen position of the hit and, in `depth`, the
// refraction pass's depth there.
vec2 refracted_hit(vec3 p, vec3 t, float max_m, out float depth) {
  mat4 view_proj = inverse(frame.inv_view_proj);
  ScreenRay r = ScreenRay(view_proj * vec4(p, 1.0), view_proj * vec4(t, 0.0), max(-t.y, 0.05), max_m);
  float below;
  vec2 uv = hit_from_the_pixel(p, r, depth, below);
  if (!kFirstHitSearch) return uv;  // no object under the water this frame (shared/surface.h)
  // The shallowest level drawn where the ray's samples above that hit are seen.
  float s_end = clamp(below / r.down, 0.0, max_m), top = below;
  vec2 from = gl_FragCoord.xy * frame.screen.zw, to = screen_at(r, s_end);
  // Only the floor is drawn outside the objects' rectangle, and the fixed point finds it there.
  vec2 lo = min(from, to) - frame.screen.zw, hi = max(from, to) + frame.screen.zw;
  bool objects = all(lessThanEqual(frame.submerged_rect.xy, hi)) && all(lessThanEqual(lo, frame.submerged_rect.zw));
  int samples = objects ? min(int(length((to - from) * frame.screen.xy) / kSamplePixels), kFirstHitSamples) : 0;
  for (int j = 1; j <= samples; ++j) {
    vec2 at = screen_at(r, s_end * float(j) / float(samples + 1));
    float d = textureLod(refraction_depth, at, 0.0).r;
    if (d >= gl_FragCoord.z) top = min(top, p.y - world_y_of(at, d));
  }
  vec2 first_uv;
  float first_depth, first_below;
  // Only an object counts: on the procedural floor, a height field, the fixed point above is already right,
  // and a search that ran only near objects must not change the floor there.
  if (top < below - 0.05 - 0.01 * below && hit_from_level(p, r, max(top, 0.0), first_uv, first_depth, first_below) &&
      first_below < below - 0.05 - 0.01 * below &&
      texelFetch(refraction_albedo, refraction_texel(first_uv), 0).a <
          0.5 * (LAGOON_REFRACTION_ALPHA_HEIGHT_FIELD + LAGOON_REFRACTION_ALPHA_OBJECT)) {
    depth = first_depth;
    return first_uv;
  }
  return uv;
}
