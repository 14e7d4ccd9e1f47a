#include "oracle/oracle.h"

#include "oracle/parallel_rows.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

// Embree 3 or 4 (cmake/Dependencies.cmake finds either; SHADOWLAB_EMBREE_MAJOR says which). The two
// differ here only in the header's folder, how one shadow ray is cast (below: cast_occluded) and the
// error codes Embree 4 added (error_name's default). Embree 4's side is written from its documented API
// (rtcOccluded1(3embree4): the arguments struct is optional) and not built here.
#if SHADOWLAB_EMBREE_MAJOR >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

namespace shadowlab {

namespace {


// Offset of a ray origin along the surface normal: a fixed fraction of the scene's size, plus a few
// dozen float ulps of the point's own coordinates so scenes far from the origin do not self-shadow.
constexpr float kSceneRelativeEpsilon = 1e-4f;
constexpr float kPositionRelativeEpsilon = 32.0f * std::numeric_limits<float>::epsilon();

const char* error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: break;  // Embree 4 has more
  }
  return "unrecognised error";
}

// The seam between Embree 3 and 4: one occlusion query for one ray. Embree 3 takes an intersection
// context; Embree 4 replaced it with an optional arguments struct whose defaults are what we want.
void cast_occluded(RTCScene scene, RTCRay& ray) {
#if SHADOWLAB_EMBREE_MAJOR >= 4
  rtcOccluded1(scene, &ray, nullptr);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(scene, &context, &ray);
#endif
}


float max_abs(const glm::vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Any unit vector perpendicular to the unit vector d.
glm::vec3 any_perpendicular(const glm::vec3& d) {
  const glm::vec3 axis = std::abs(d.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(d, axis));
}

}  // namespace

// What the occlusion filter of an alpha-tested (MASK) caster needs: the cut-out of Mesh::cut_out, from a
// copy of the mesh's material (the texture's pixels shared), so the oracle outlives the scene it was built
// from. A hit whose point is cut out is rejected and the ray goes on, as the shadow map's discard does.
struct MaskedCaster {
  Mesh mesh;  // indices, uvs, colours and the material; no positions
  std::vector<Texture> textures;

  static void filter(const RTCFilterFunctionNArguments* args) {
    const auto* self = static_cast<const MaskedCaster*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
      if (args->valid[i] == 0) continue;
      const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
      const unsigned t = RTCHitN_primID(args->hit, args->N, i);
      if (self->mesh.cut_out(self->textures, t, u, v)) args->valid[i] = 0;
    }
  }
};

struct Oracle::Impl {
  struct Band;
  struct Job;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<MaskedCaster>> masked;  // user data of the MASK geometries
  float scene_epsilon = 0.0f;  // kSceneRelativeEpsilon x the scene's bounding-box diagonal
  std::size_t triangles = 0;

  std::mutex error_mutex;
  std::string error_message;  // the last message Embree passed to the error callback

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  static void on_error(void* user, RTCError code, const char* message) {
    auto* self = static_cast<Impl*>(user);
    const std::lock_guard lock(self->error_mutex);
    self->error_message = std::string(error_name(code)) + (message ? std::string(": ") + message : std::string());
  }

  // Throws if the last Embree call on this thread failed.
  void check(const char* what) {
    const RTCError code = rtcGetDeviceError(device);
    if (code == RTC_ERROR_NONE) return;
    std::string message;
    {
      const std::lock_guard lock(error_mutex);
      message = error_message.empty() ? error_name(code) : error_message;
    }
    throw std::runtime_error(std::string("oracle: Embree failed in ") + what + ": " + message);
  }

  // Copies a shadow-casting mesh into the scene (mesh index m for messages).
  void attach(const Mesh& mesh, std::size_t m, const std::vector<Texture>& textures) {
    const std::size_t vertex_count = mesh.positions.size();
    const std::size_t triangle_count = mesh.triangle_count();
    for (std::size_t k = 0; k < triangle_count * 3; ++k) {
      if (mesh.indices[k] >= vertex_count) {
        throw std::invalid_argument("oracle: mesh " + std::to_string(m) + " (\"" + mesh.name + "\") has index " +
                                    std::to_string(mesh.indices[k]) + " past its " + std::to_string(vertex_count) +
                                    " vertices");
      }
  }
  if (vertex_count > std::numeric_limits<unsigned>::max() || triangle_count > std::numeric_limits<unsigned>::max()) {
    throw std::invalid_argument("oracle: mesh \"" + mesh.name + "\" is too large for Embree");
  }

  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  check("rtcNewGeometry");
  // Copied buffers: Embree pads them as its SIMD loads need, and the oracle outlives the Scene.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), vertex_count));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), triangle_count));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    check("rtcSetNewGeometryBuffer");
    throw std::runtime_error("oracle: Embree could not allocate the buffers of mesh \"" + mesh.name + "\"");
  }
  for (std::size_t v = 0; v < vertex_count; ++v) {
    vertices[3 * v + 0] = mesh.positions[v].x;
    vertices[3 * v + 1] = mesh.positions[v].y;
    vertices[3 * v + 2] = mesh.positions[v].z;
  }
  std::copy_n(mesh.indices.begin(), triangle_count * 3, indices);
  if (mesh.alpha_mode == AlphaMode::Mask) {
    auto caster = std::make_unique<MaskedCaster>();
    caster->mesh.indices = mesh.indices;
    caster->mesh.uvs = mesh.uvs;
    caster->mesh.colors = mesh.colors;
    caster->mesh.alpha = mesh.alpha;
    caster->mesh.texture = mesh.texture;
    caster->mesh.alpha_mode = mesh.alpha_mode;
    caster->mesh.alpha_cutoff = mesh.alpha_cutoff;
    caster->mesh.shape_alpha = mesh.shape_alpha;
    caster->textures = textures;
    rtcSetGeometryUserData(geometry, caster.get());
    rtcSetGeometryOccludedFilterFunction(geometry, &MaskedCaster::filter);
    rtcSetGeometryIntersectFilterFunction(geometry, &MaskedCaster::filter);
    masked.push_back(std::move(caster));
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);  // the scene holds its own reference
  check("attaching a triangle mesh");
  triangles += triangle_count;
  }

  float epsilon(const glm::vec3& p) const { return scene_epsilon + kPositionRelativeEpsilon * max_abs(p); }

  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float max_distance) const {
    if (!(max_distance > 0.0f)) return false;  // also NaN
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.tnear = 0.0f;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.time = 0.0f;
    ray.tfar = max_distance;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    cast_occluded(scene, ray);
    return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit and leaves it alone otherwise
  }
};

Oracle::Oracle(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.device = rtcNewDevice(nullptr);
  if (!im.device) {
    throw std::runtime_error(std::string("oracle: cannot create the Embree device: ") +
                             error_name(rtcGetDeviceError(nullptr)));
  }
  rtcSetDeviceErrorFunction(im.device, &Impl::on_error, &im);

  // The offset scale comes from every mesh, shadow casters or not (receivers count too).
  Bounds bounds;
  for (const Mesh& mesh : scene.meshes) {
    for (const glm::vec3& p : mesh.positions) {
      if (finite(p)) bounds.extend(p);
    }
  }
  if (!bounds.empty()) {
    const float diagonal = glm::length(bounds.extent());
    if (std::isfinite(diagonal)) im.scene_epsilon = kSceneRelativeEpsilon * diagonal;
  }

  const auto start = std::chrono::steady_clock::now();
  im.scene = rtcNewScene(im.device);
  im.check("rtcNewScene");
  // Robust traversal: the oracle favours exactness (no rays slipping between triangles) over speed.
  rtcSetSceneFlags(im.scene, RTC_SCENE_FLAG_ROBUST);
  im.check("rtcSetSceneFlags");

  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    // A mesh that casts no shadow is not in the shadow maps either, so it does not occlude the truth.
    if (!mesh.casts_shadow || mesh.triangle_count() == 0 || mesh.positions.empty()) continue;
    im.attach(mesh, m, scene.textures);
  }

  rtcCommitScene(im.scene);
  im.check("rtcCommitScene");
  build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Oracle::~Oracle() = default;

std::size_t Oracle::triangle_count() const { return impl_->triangles; }

bool Oracle::occluded(const glm::vec3& origin, const glm::vec3& direction, float max_distance) const {
  return impl_->occluded(origin, direction, max_distance);
}

float Oracle::ray_epsilon(const glm::vec3& p) const { return impl_->epsilon(p); }

std::size_t checked_pixel_count(const GBuffer& gbuffer, const char* who) {
  if (gbuffer.width < 0 || gbuffer.height < 0) throw std::invalid_argument(std::string(who) + ": negative G-buffer size");
  const std::size_t width = static_cast<std::size_t>(gbuffer.width);
  const std::size_t height = static_cast<std::size_t>(gbuffer.height);
  const std::size_t count = width * height;
  if (gbuffer.position.size() != count || gbuffer.normal.size() != count || gbuffer.covered.size() != count) {
    throw std::invalid_argument(std::string(who) + ": G-buffer arrays do not match its " + std::to_string(width) + "x" +
                                std::to_string(height) + " size");
  }
  return count;
}

namespace {

// Toward a directional light, unit length (zero for a positional light, whose position is checked).
glm::vec3 checked_light_direction(const OracleLight& light) {
  if (light.positional) {
    if (!finite(light.position)) throw std::invalid_argument("oracle: light position is not finite");
    return glm::vec3(0.0f);
  }
  const float len = glm::length(light.to_light);
  if (!(len > 0.0f) || !std::isfinite(len)) throw std::invalid_argument("oracle: light direction is zero or not finite");
  return light.to_light / len;
}

}  // namespace

// The band circle of one evaluation, sampled at fixed angles.
struct Oracle::Impl::Band {
  bool screen = false;      // a fixed width in screen pixels: classified once every pixel is known
  bool point = false;       // no radius: every valid pixel is interior
  bool everything = false;  // an angular radius of 90 degrees or more covers the whole half-space
  std::vector<float> cos_a, sin_a;
  float radius_world = 0.0f;  // directional
  float tan_angle = 0.0f;     // positional
  float grazing_n_dot_l = 0.0f;  // pixels lit at n . l below this are in the band whatever their neighbours

  Band(const BandSpec& band, const OracleLight& light)
      : screen(band.fixed_screen_pixels > 0), grazing_n_dot_l(band.grazing_n_dot_l) {
    const int samples = screen ? 0 : std::max(band.samples, 0);
    cos_a.resize(static_cast<std::size_t>(samples));
    sin_a.resize(static_cast<std::size_t>(samples));
    for (int k = 0; k < samples; ++k) {
      const double a = 2.0 * std::numbers::pi * k / samples;
      cos_a[static_cast<std::size_t>(k)] = static_cast<float>(std::cos(a));
      sin_a[static_cast<std::size_t>(k)] = static_cast<float>(std::sin(a));
    }
    radius_world = band.radius_texels * light.texel_world_size;
    const float radius_angle = band.radius_texels * light.texel_angle;
    tan_angle = std::tan(radius_angle);
    point = light.positional ? !(radius_angle > 0.0f) : !(radius_world > 0.0f);
    everything = light.positional && !point &&
                 !(radius_angle < 0.5f * std::numbers::pi_v<float> && std::isfinite(tan_angle));
  }
};

// One evaluation: the G-buffer, the light and the band, and the truth being filled in.
struct Oracle::Impl::Job {
  const Impl& im;
  const GBuffer& gbuffer;
  const OracleLight& light;
  glm::vec3 to_light_dir;
  const Band& band;
  Truth& truth;
  std::vector<std::uint8_t>& grazing;  // per pixel, when band.grazing_n_dot_l > 0: lit at a grazing angle

  // Shadow ray from a point on the surface (offset along its normal) toward the light.
  bool shadowed_from(const glm::vec3& q, const glm::vec3& n) const {
    const float eps = im.epsilon(q);
    const glm::vec3 origin = q + n * eps;
    if (!light.positional) return im.occluded(origin, to_light_dir, std::numeric_limits<float>::infinity());
    const glm::vec3 d = light.position - origin;
    const float dist = glm::length(d);
    if (!(dist > eps)) return false;  // the light is within the offset: nothing can be in between
    return im.occluded(origin, d / dist, dist - eps);
  }

  // Classifies pixel i (valid, lit, interior); returns the rays cast.
  std::uint64_t pixel(std::size_t i) const {
    if (!gbuffer.covered[i]) return 0;
    const glm::vec3 p = gbuffer.position[i];
    glm::vec3 n = gbuffer.normal[i];
    if (!finite(p) || !finite(n)) return 0;
    const float n_len = glm::length(n);
    if (!(n_len > 0.0f)) return 0;
    n /= n_len;

    glm::vec3 l = to_light_dir;
    float dist = 0.0f;
    if (light.positional) {
      const glm::vec3 d = light.position - p;
      dist = glm::length(d);
      if (!(dist > 0.0f) || !std::isfinite(dist)) return 0;
      l = d / dist;
    }
    const float n_dot_l = glm::dot(n, l);
    if (!(n_dot_l > 0.0f)) return 0;

    truth.valid[i] = 1;
    const bool shadowed = shadowed_from(p, n);
    truth.lit[i] = shadowed ? 0 : 1;
    std::uint64_t rays = 1;
    if (n_dot_l < band.grazing_n_dot_l) {
      grazing[i] = 1;
      return rays;  // in the band whatever its neighbours
    }
    if (band.screen) return rays;      // classified once every pixel is known
    if (band.everything) return rays;  // interior stays 0
    if (band.point || band.cos_a.empty()) {
      truth.interior[i] = 1;
      return rays;
    }
    const bool interior = light.positional ? positional_interior(p, n, l, dist, shadowed, rays)
                                           : directional_interior(p, n, l, n_dot_l, shadowed, rays);
    truth.interior[i] = interior ? 1 : 0;
    return rays;
  }

  // Whether every point of the band circle around p agrees with p (counting the rays cast).
  bool directional_interior(const glm::vec3& p, const glm::vec3& n, const glm::vec3& l, float n_dot_l, bool shadowed,
                            std::uint64_t& rays) const {
    bool interior = true;
    for (std::size_t k = 0; k < band.cos_a.size() && interior; ++k) {
      const glm::vec3 o = band.radius_world * (band.cos_a[k] * light.image_x + band.sin_a[k] * light.image_y);
      // Slide along the light direction back onto the tangent plane at p.
      const float t = -glm::dot(n, o) / n_dot_l;
      const glm::vec3 q = p + o + t * l;
      if (!finite(q)) return false;
      ++rays;
      interior = shadowed_from(q, n) == shadowed;
    }
    return interior;
  }

  bool positional_interior(const glm::vec3& p, const glm::vec3& n, const glm::vec3& l, float dist, bool shadowed,
                           std::uint64_t& rays) const {
    // Offsets perpendicular to the direction from the light to p, oriented by the image axes.
    const glm::vec3 from_light = -l;
    glm::vec3 u = light.image_x - glm::dot(light.image_x, from_light) * from_light;
    if (!(glm::length(u) > 1e-3f)) u = light.image_y - glm::dot(light.image_y, from_light) * from_light;
    u = glm::length(u) > 1e-3f ? glm::normalize(u) : any_perpendicular(from_light);
    const glm::vec3 v = glm::cross(from_light, u);
    const float radius = dist * band.tan_angle;
    const glm::vec3 light_to_p = p - light.position;
    const float num = glm::dot(n, light_to_p);  // < 0: the light is in front of the surface
    bool interior = true;
    for (std::size_t k = 0; k < band.cos_a.size() && interior; ++k) {
      const glm::vec3 w = light_to_p + radius * (band.cos_a[k] * u + band.sin_a[k] * v);
      // Where the line from the light through p + o meets the tangent plane at p. If it never does
      // (the circle reaches past the plane's horizon), the pixel is on an edge.
      const float denom = glm::dot(n, w);
      const float s = num / denom;
      if (!(denom < 0.0f) || !(s > 0.0f) || !std::isfinite(s)) return false;
      const glm::vec3 q = light.position + s * w;
      if (!finite(q)) return false;
      ++rays;
      interior = shadowed_from(q, n) == shadowed;
    }
    return interior;
  }

  // Every pixel, rows handed out one at a time to kTruthThreads threads; every pixel is independent, so
  // the output does not depend on timing. Returns the rays cast.
  std::uint64_t all_pixels() const {
    const auto width = static_cast<std::size_t>(gbuffer.width), height = static_cast<std::size_t>(gbuffer.height);
    return for_each_row_parallel(height, kTruthThreads, [&](std::size_t y) {
      std::uint64_t rays = 0;
      for (std::size_t x = 0; x < width; ++x) rays += pixel(y * width + x);
      return rays;
    });
  }
};

namespace {

// A screen band of k pixels: interior where no valid pixel of the other truth lies within the
// (2k+1)^2 square (and the pixel is not lit at a grazing angle). Summed-area tables of valid-lit and
// valid-shadowed pixels answer each square in constant time.
void classify_screen_band(Truth& truth, std::size_t k, const std::vector<std::uint8_t>& grazing) {
  const auto width = static_cast<std::size_t>(truth.width), height = static_cast<std::size_t>(truth.height);
  const std::size_t stride = width + 1;
  std::vector<std::uint32_t> lit_sum(stride * (height + 1), 0), shadow_sum(stride * (height + 1), 0);
  for (std::size_t y = 0; y < height; ++y) {
    std::uint32_t row_lit = 0, row_shadow = 0;
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t i = y * width + x;
      row_lit += truth.valid[i] && truth.lit[i];
      row_shadow += truth.valid[i] && !truth.lit[i];
      lit_sum[(y + 1) * stride + x + 1] = lit_sum[y * stride + x + 1] + row_lit;
      shadow_sum[(y + 1) * stride + x + 1] = shadow_sum[y * stride + x + 1] + row_shadow;
    }
  }
  // Pixels of s's kind in the inclusive rectangle [x0, x1] x [y0, y1] (unsigned wrap-around cancels).
  auto box = [&](const std::vector<std::uint32_t>& s, std::size_t x0, std::size_t y0, std::size_t x1, std::size_t y1) {
    return s[(y1 + 1) * stride + x1 + 1] - s[y0 * stride + x1 + 1] - s[(y1 + 1) * stride + x0] + s[y0 * stride + x0];
  };
  for (std::size_t y = 0; y < height; ++y) {
    const std::size_t y0 = y > k ? y - k : 0, y1 = std::min(height - 1, y + k);
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t i = y * width + x;
      if (!truth.valid[i]) continue;
      const std::size_t x0 = x > k ? x - k : 0, x1 = std::min(width - 1, x + k);
      const std::uint32_t others = box(truth.lit[i] ? shadow_sum : lit_sum, x0, y0, x1, y1);
      truth.interior[i] = others == 0 && (grazing.empty() || !grazing[i]) ? 1 : 0;
    }
  }
}

}  // namespace

Truth Oracle::evaluate(const GBuffer& gbuffer, const OracleLight& light, const BandSpec& band) const {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t count = checked_pixel_count(gbuffer, "oracle");
  const glm::vec3 to_light_dir = checked_light_direction(light);
  Truth truth;
  truth.width = gbuffer.width;
  truth.height = gbuffer.height;
  truth.valid.assign(count, 0);
  truth.lit.assign(count, 0);
  truth.interior.assign(count, 0);
  std::vector<std::uint8_t> grazing(band.grazing_n_dot_l > 0.0f ? count : 0, 0);
  const Impl::Band circle(band, light);
  truth.rays = Impl::Job{*impl_, gbuffer, light, to_light_dir, circle, truth, grazing}.all_pixels();
  if (circle.screen) classify_screen_band(truth, static_cast<std::size_t>(band.fixed_screen_pixels), grazing);
  truth.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return truth;
}

}  // namespace shadowlab
