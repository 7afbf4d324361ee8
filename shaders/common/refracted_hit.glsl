// Where the refracted ray from a point of the water surface meets the floor or a submerged object (issue 39):
// the refraction pass drew them from the camera into `refraction_depth`, so a point q along the ray can be
// looked up by projecting it onto the screen. The search is a fixed point on the depth below the surface:
// guess how far along the ray the hit is (first from what the pixel itself sees), project, read the point
// drawn there, and take its depth below the surface point for the next guess. A level floor is exact after
// the first step and an object's level top after the second. The point is where a ray trace through the displaced surface puts it, not
// a flat screen offset. It follows what is drawn, so without a floor a submerged object is found only
// where the pixel's own line of sight already meets it. Needs `frame`, `refraction_depth` and the
// fragment's depth (gl_FragCoord.z) to reject what stands in front of the water.

const int kRefractedSteps = 4;

vec3 world_of(vec2 uv, float depth) {
  vec4 c = frame.inv_view_proj * vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
  return c.xyz / c.w;
}

// world_of(uv, depth).y alone: two rows of the inverse instead of four.
float world_y_of(vec2 uv, float depth) {
  vec4 ndc = vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
  mat4 m = frame.inv_view_proj;
  return dot(vec4(m[0].y, m[1].y, m[2].y, m[3].y), ndc) / dot(vec4(m[0].w, m[1].w, m[2].w, m[3].w), ndc);
}

// `p`: the surface point; `t`: the refracted direction (unit, downward); `max_m`: the longest path worth
// following (the LUT's depth along the ray). Returns the screen position of the hit and, in `depth`, the
// refraction pass's depth there. The steps stop when a guess reads back the depth it came from. When they
// do not settle, the ray passes behind an object as the camera sees it, to floor the object hides; the
// deepest point found (floor beside the object) stands in for it, not the object. Where the ray meets
// something in front of the water, the last point found (at first the pixel's own).
vec2 refracted_hit(vec3 p, vec3 t, float max_m, out float depth) {
  vec2 uv = gl_FragCoord.xy * frame.screen.zw;
  depth = textureLod(refraction_depth, uv, 0.0).r;
  float down = max(-t.y, 0.05);
  float below = p.y - world_y_of(uv, depth), last = -1.0;
  // The clip position is linear along the ray: p's and t's once, then each guess is a multiply-add. The
  // projection is the inverse's inverse: reading frame.view_proj in this fragment shader makes lavapipe's
  // resident memory grow by about 0.9 MiB a frame (Mesa 22.3; `lagoon soak` +32 % in 100 frames), this
  // does not.
  mat4 view_proj = inverse(frame.inv_view_proj);
  vec4 clip_p = view_proj * vec4(p, 1.0), clip_t = view_proj * vec4(t, 0.0);
  vec2 deepest_uv = uv;
  float deepest_depth = depth, deepest = below;
  for (int i = 0; i < kRefractedSteps; ++i) {
    float s = clamp(below / down, 0.0, max_m);
    if (abs(s - last) < 0.01 + 0.01 * s) return uv;  // the guess reads back its own depth: settled
    last = s;
    // Off the screen nothing was drawn: the edge's nearest pixel stands in (a level floor continues there).
    vec4 clip = clip_p + s * clip_t;
    vec2 next = clamp(vec2(0.5, 0.5) + vec2(0.5, -0.5) * clip.xy / clip.w, vec2(0.0), vec2(1.0));
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
  if (abs(clamp(below / down, 0.0, max_m) - last) < 0.01 + 0.01 * last) return uv;
  depth = deepest_depth;
  return deepest_uv;
}
