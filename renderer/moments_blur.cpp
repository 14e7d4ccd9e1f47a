// The moments' Gaussian blur (see moments_pass.h): the weights, the CPU reference, and the three
// methods' GPU passes: the taught separable shader, the fast separable blur (compute shaders, fused for
// small radii, or fragment shaders with bilinear taps) and the brute-force 2D pass.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "renderer/moments_pass.h"

#include "renderer/blur_passes.h"

namespace shadowlab {

namespace {

// The bilinear taps of the fast blur on the + side of the centre (the - side mirrors them): texels
// 2k - 1 and 2k share one linearly filtered fetch at offset (i1 w1 + i2 w2) / (w1 + w2) with weight
// w1 + w2 (the last texel alone when the radius is odd). Index 0 is unused (the centre is fetched alone).
std::vector<float> bilinear_taps(const std::vector<double>& w, int radius) {
  const int pairs = (radius + 1) / 2;
  std::vector<float> taps(static_cast<std::size_t>(2 * (pairs + 1)), 0.0f);
  for (int k = 1; k <= pairs; ++k) {
    const int i1 = 2 * k - 1, i2 = 2 * k;
    const double w1 = w[static_cast<std::size_t>(i1)];
    const double w2 = i2 <= radius ? w[static_cast<std::size_t>(i2)] : 0.0;
    taps[static_cast<std::size_t>(2 * k)] = static_cast<float>((i1 * w1 + i2 * w2) / (w1 + w2));
    taps[static_cast<std::size_t>(2 * k + 1)] = static_cast<float>(w1 + w2);
  }
  return taps;
}

// The brute-force shader's weight array (shaders/vsm/brute_blur.frag).
constexpr int kMaxBrute2dRadius = 64;

std::vector<float> to_float(const std::vector<double>& v) { return {v.begin(), v.end()}; }

// The fast blur's compute shader: texels per invocation along the blur direction, and the work group.
// 16 outputs read 16 + 2r texels: 3 reads per output at r = 16 instead of 33. Measured on llvmpipe
// (2 cores, 1024^2): 8 and 16 outputs per invocation about equal at r <= 4, 16 clearly better at r = 16.
constexpr int kFastOutputs = 16;
constexpr int kFastGroupX = 32, kFastGroupY = 8;

// The unrolled body of fast_blur.comp (every array index a constant, so the window stays in registers).
std::string fast_fetch_code(int radius) {
  std::string code;
  for (int j = 0; j < kFastOutputs + 2 * radius; ++j)
    code += "t[" + std::to_string(j) + "] = fetch(" + std::to_string(j) + "); ";
  return code;
}

std::string fast_sum_code(int radius) {
  std::string code;
  for (int k = 0; k < kFastOutputs; ++k) {
    const int c = k + radius;
    code += "store(" + std::to_string(k) + ", u_weights[0] * t[" + std::to_string(c) + "]";
    for (int i = 1; i <= radius; ++i)
      code += " + u_weights[" + std::to_string(i) + "] * (t[" + std::to_string(c + i) + "] + t[" +
              std::to_string(c - i) + "])";
    code += "); ";
  }
  return code;
}

// The fused fast blur (shaders/vsm/fast_blur2d.comp): the block each invocation writes, its work group,
// and the largest radius it serves. Measured on llvmpipe (2 cores, 1024^2 RG32F, against the taught
// blur in the same run): fused 2.2x / 3.6x / 3.5x at r 1 / 4 / 8, two dispatches 1.2-1.8x / 1.5-2.4x /
// 3.3x; 16 x 4 blocks cost the same as 16 x 8 at r1 and 10 % more at r2. Above r4 the rows it reads
// ((8 + 2r) x (16 + 2r) per 128 outputs) grow faster than the two-dispatch path's (1 + 2r / 16 per output).
constexpr int kFusedX = 16, kFusedY = 8, kFusedGroupX = 8, kFusedGroupY = 8, kFusedMaxRadius = 4;

std::string fused_body_code(int radius) {
  auto n = [](int v) { return std::to_string(v); };
  auto sum = [&](auto term) {  // w_0 term(0) + sum_i w_i (term(i) + term(-i))
    std::string code = "u_weights[0] * " + term(0);
    for (int i = 1; i <= radius; ++i) code += " + u_weights[" + n(i) + "] * (" + term(i) + " + " + term(-i) + ")";
    return code;
  };
  std::string code;
  for (int j = 0; j < kFusedY + 2 * radius; ++j) {
    code += "{ ";
    for (int k = 0; k < kFusedX + 2 * radius; ++k) code += "vec2 t" + n(k) + " = fetch(" + n(k) + ", " + n(j) + "); ";
    for (int k = 0; k < kFusedX; ++k)
      code += "h" + n(j) + "_" + n(k) + " = " + sum([&](int i) { return "t" + n(k + radius + i); }) + "; ";
    code += "} ";
  }
  std::string declare = "vec2 ";
  for (int j = 0; j < kFusedY + 2 * radius; ++j)
    for (int k = 0; k < kFusedX; ++k) declare += (j || k ? ", h" : "h") + n(j) + "_" + n(k);
  code = declare + "; " + code;
  for (int m = 0; m < kFusedY; ++m)
    for (int k = 0; k < kFusedX; ++k)
      code += "store(" + n(k) + ", " + n(m) + ", " + sum([&](int i) { return "h" + n(m + radius + i) + "_" + n(k); }) + "); ";
  return code;
}

GlProgram build_compute_program(const ProgramDesc& desc, const std::filesystem::path& file) {
  std::vector<std::filesystem::path> files;
  std::string error;
  const std::string source = preprocess_shader(data_dir() / file, desc, files, error);
  if (!error.empty()) throw std::runtime_error("cannot build the fast blur: " + error);
  GlShader shader = make_shader(GL_COMPUTE_SHADER);
  const char* text = source.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GlProgram program = GlProgram::create();
  glAttachShader(program.id(), shader.id());
  glLinkProgram(program.id());
  glDetachShader(program.id(), shader.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string log(4096, '\0');
    glGetShaderInfoLog(shader.id(), static_cast<GLsizei>(log.size()), nullptr, log.data());
    throw std::runtime_error("cannot build the fast blur (" + file.string() + "): " + std::string(log.c_str()));
  }
  return program;
}

}  // namespace

BlurMethod blur_method_from_name(const std::string& name) {
  if (name == "separable") return BlurMethod::Separable;
  if (name == "fast") return BlurMethod::Fast;
  if (name == "brute2d") return BlurMethod::Brute2D;
  throw std::invalid_argument("unknown blur method '" + name + "' (separable, fast, brute2d)");
}

const char* blur_method_name(BlurMethod method) {
  switch (method) {
    case BlurMethod::Separable: return "separable";
    case BlurMethod::Fast: return "fast";
    case BlurMethod::Brute2D: return "brute2d";
  }
  return "?";
}

std::vector<double> gaussian_weights(int radius, double sigma) {
  std::vector<double> w(static_cast<std::size_t>(radius + 1));
  double sum = 0.0;
  for (int i = 0; i <= radius; ++i) {
    w[static_cast<std::size_t>(i)] = std::exp(-i * i / (2.0 * sigma * sigma));
    sum += (i == 0 ? 1.0 : 2.0) * w[static_cast<std::size_t>(i)];
  }
  for (auto& x : w) x /= sum;
  return w;
}

std::vector<double> cpu_gaussian_blur(const std::vector<float>& rg, int n, int radius, double sigma) {
  const std::vector<double> w = gaussian_weights(radius, sigma);
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * 2;
  std::vector<double> in(rg.begin(), rg.end()), tmp(count, 0.0), out(count, 0.0);
  auto pass = [&](const std::vector<double>& src, std::vector<double>& dst, int dx, int dy) {
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int c = 0; c < 2; ++c) {
          double acc = 0.0;
          for (int i = -radius; i <= radius; ++i) {
            const int sx = std::clamp(x + i * dx, 0, n - 1), sy = std::clamp(y + i * dy, 0, n - 1);
            acc += w[static_cast<std::size_t>(std::abs(i))] * src[(static_cast<std::size_t>(sy) * n + sx) * 2 + c];
          }
          dst[(static_cast<std::size_t>(y) * n + x) * 2 + c] = acc;
        }
  };
  pass(in, tmp, 1, 0);
  pass(tmp, out, 0, 1);
  return out;
}

void MomentsPass::blur(int radius, float sigma, GLuint empty_vao, const PassWrapper& around) {
  if (!blur_texture_) throw std::logic_error("MomentsPass::blur without a blur target");
  for (auto [program, u] : {std::pair{&blur_x_, &blur_x_u_}, std::pair{&blur_y_, &blur_y_u_}}) {
    if (u->generation != program->generation()) {
      const GLuint id = program->id();
      *u = {program->generation(), Uniform(id, "u_moments"), Uniform(id, "u_blur_radius"), Uniform(id, "u_blur_sigma")};
    }
    glUseProgram(program->id());
    u->radius.set(radius);
    u->sigma.set(sigma);
  }
  // The course's two passes, X then Y through the ping-pong texture: lab 5's GL solution
  // (renderer/blur_passes.cpp) binds, sets the viewport and the uniforms; this draws.
  BlurJob job{moments_texture_.id(), moments_fbo_.id(), size_, {blur_fbo_.id(), blur_texture_.id(), size_},
              blur_x_.id(), blur_y_.id(), {}};
  job.draw = [&](int pass) {
    const auto draw = [&] {
      glBindVertexArray(empty_vao);
      if (!four_moments_) {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        return;
      }
      // The shader blurs .rg and writes it to both pairs (shaders/vsm/blur.frag): the first pair as is,
      // then the second, read through a swizzle (B, A) of the bound source and written through the mask
      // (B, A) only.
      const GLint identity[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA}, second[4] = {GL_BLUE, GL_ALPHA, GL_BLUE, GL_ALPHA};
      glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, second);
      glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_TRUE);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, identity);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    };
    around ? around(pass, draw) : draw();
  };
  code_.run_blur_passes(job);
  glEnable(GL_DEPTH_TEST);
}

void MomentsPass::blur_fast(int direction, int radius, float sigma, GLuint empty_vao) {
  if (!blur_texture_) throw std::logic_error("MomentsPass::blur_fast without a blur target");
  if (fast_path_ == FastPath::Compute) {
    blur_fast_compute(direction, radius, sigma);
  } else {
    blur_fast_fragment(direction, radius, sigma, empty_vao);
  }
}

void MomentsPass::blur_fused_compute(int direction, int radius, float sigma) {
  if (direction == 1) {
    // The fused pass wrote B: B becomes the moments texture (what the lit pass, read-backs and the next
    // moments pass use) and A the ping-pong one. Both have the same size, format and filtering, so
    // swapping them and re-attaching each framebuffer's colour costs nothing, where a copy costs a pass.
    std::swap(moments_texture_, blur_texture_);
    for (const auto& [fbo, texture] : {std::pair{moments_fbo_.id(), moments_texture_.id()}, std::pair{blur_fbo_.id(), blur_texture_.id()}}) {
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return;
  }
  const auto key = std::make_pair(radius, format_);
  auto it = fused_compute_.find(key);
  if (it == fused_compute_.end()) {
    const ProgramDesc desc{{},
                           {},
                           {},
                           {{"RADIUS", std::to_string(radius)},
                            {"BLOCK_X", std::to_string(kFusedX)},
                            {"BLOCK_Y", std::to_string(kFusedY)},
                            {"LOCAL_X", std::to_string(kFusedGroupX)},
                            {"LOCAL_Y", std::to_string(kFusedGroupY)},
                            {"MOMENTS_FORMAT", format_ == "RG16F" ? "rg16f" : "rg32f"},
                            {"FUSED_BODY", fused_body_code(radius)}},
                           {}};
    it = fused_compute_.emplace(key, build_compute_program(desc, "shaders/vsm/fast_blur2d.comp")).first;
  }
  const int nx = (size_ + kFusedX - 1) / kFusedX, ny = (size_ + kFusedY - 1) / kFusedY;
  dispatch_blur(it->second.id(), moments_texture_.id(), blur_texture_.id(), radius, sigma,
                (nx + kFusedGroupX - 1) / kFusedGroupX, (ny + kFusedGroupY - 1) / kFusedGroupY);
}

void MomentsPass::dispatch_blur(GLuint program, GLuint source, GLuint target, int radius, float sigma, int groups_x,
                                int groups_y) {
  const std::vector<float> weights = to_float(gaussian_weights(radius, sigma));
  glUseProgram(program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, source);
  glUniform1i(glGetUniformLocation(program, "u_moments"), 0);
  glBindImageTexture(0, target, 0, GL_FALSE, 0, GL_WRITE_ONLY, format_ == "RG16F" ? GL_RG16F : GL_RG32F);
  glUniform1i(glGetUniformLocation(program, "u_out"), 0);
  glUniform1fv(glGetUniformLocation(program, "u_weights"), static_cast<GLsizei>(weights.size()), weights.data());
  glDispatchCompute(static_cast<GLuint>(groups_x), static_cast<GLuint>(groups_y), 1);
  // The next pass samples what was stored; the lit pass, read-backs and blits read it too.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                  GL_PIXEL_BUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
}

void MomentsPass::blur_fast_compute(int direction, int radius, float sigma) {
  if (radius <= kFusedMaxRadius) {
    blur_fused_compute(direction, radius, sigma);
    return;
  }
  const auto key = std::make_pair(radius, format_);
  auto it = fast_compute_.find(key);
  if (it == fast_compute_.end()) {
    ComputeBlur c;
    for (int d : {0, 1}) {
      const ProgramDesc desc{{},
                             {},
                             {},
                             {{"BLUR_DIRECTION", d == 0 ? "ivec2(1, 0)" : "ivec2(0, 1)"},
                              {"RADIUS", std::to_string(radius)},
                              {"OUTPUTS", std::to_string(kFastOutputs)},
                              {"LOCAL_X", std::to_string(kFastGroupX)},
                              {"LOCAL_Y", std::to_string(kFastGroupY)},
                              {"MOMENTS_FORMAT", format_ == "RG16F" ? "rg16f" : "rg32f"},
                              {"FAST_BLUR_FETCHES", fast_fetch_code(radius)},
                              {"FAST_BLUR_SUMS", fast_sum_code(radius)}},
                             {}};
      (d == 0 ? c.x : c.y) = build_compute_program(desc, "shaders/vsm/fast_blur.comp");
    }
    it = fast_compute_.emplace(key, std::move(c)).first;
  }
  const int chunks = (size_ + kFastOutputs - 1) / kFastOutputs;
  const int nx = direction == 0 ? chunks : size_, ny = direction == 0 ? size_ : chunks;
  // X reads A and writes B, Y reads B and writes A, as the taught passes do.
  dispatch_blur(direction == 0 ? it->second.x.id() : it->second.y.id(),
                direction == 0 ? moments_texture_.id() : blur_texture_.id(),
                direction == 0 ? blur_texture_.id() : moments_texture_.id(), radius, sigma,
                (nx + kFastGroupX - 1) / kFastGroupX, (ny + kFastGroupY - 1) / kFastGroupY);
}

void MomentsPass::blur_fast_fragment(int direction, int radius, float sigma, GLuint empty_vao) {
  auto it = fast_fragment_.find(radius);
  if (it == fast_fragment_.end()) {
    FragmentBlur f;
    auto desc = [&](const char* dir) {
      return ProgramDesc{"shaders/fullscreen.vert",
                         {},
                         "shaders/vsm/fast_blur.frag",
                         {{"BLUR_DIRECTION", dir}, {"RADIUS", std::to_string(radius)},
                          {"PAIRS", std::to_string((radius + 1) / 2)}},
                         {}};
    };
    f.x = ReloadableProgram(desc("vec2(1.0, 0.0)"));
    f.y = ReloadableProgram(desc("vec2(0.0, 1.0)"));
    if (!f.x.rebuild() || !f.y.rebuild())
      throw std::runtime_error("cannot build the fast blur:\n" + f.x.error() + f.y.error());
    it = fast_fragment_.emplace(radius, std::move(f)).first;
  }
  const GLuint id = direction == 0 ? it->second.x.id() : it->second.y.id();
  const std::vector<double> w = gaussian_weights(radius, sigma);
  const std::vector<float> taps = bilinear_taps(w, radius);
  bind_color_target(direction == 0 ? blur_fbo_.id() : moments_fbo_.id(), size_, size_);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(id);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, direction == 0 ? moments_texture_.id() : blur_texture_.id());
  glUniform1i(glGetUniformLocation(id, "u_moments"), 0);
  glUniform1f(glGetUniformLocation(id, "u_center_weight"), static_cast<float>(w[0]));
  glUniform2fv(glGetUniformLocation(id, "u_taps"), static_cast<GLsizei>(taps.size() / 2), taps.data());
  glUniform2f(glGetUniformLocation(id, "u_inv_size"), 1.0f / static_cast<float>(size_), 1.0f / static_cast<float>(size_));
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
}

void MomentsPass::blur_brute2d(int radius, float sigma, GLuint empty_vao) {
  if (!blur_texture_) throw std::logic_error("MomentsPass::blur_brute2d without a blur target");
  if (!brute_.valid()) {
    brute_ = ReloadableProgram({"shaders/fullscreen.vert", {}, "shaders/vsm/brute_blur.frag", {}, {}});
    if (!brute_.rebuild()) throw std::runtime_error("cannot build the brute-force blur:\n" + brute_.error());
  }
  if (radius > kMaxBrute2dRadius) throw std::invalid_argument("brute2d blur: radius above 64");
  const GLuint id = brute_.id();
  const std::vector<float> wf = to_float(gaussian_weights(radius, sigma));
  bind_color_target(blur_fbo_.id(), size_, size_);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(id);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, moments_texture_.id());
  glUniform1i(glGetUniformLocation(id, "u_moments"), 0);
  glUniform1i(glGetUniformLocation(id, "u_blur_radius"), radius);
  glUniform1fv(glGetUniformLocation(id, "u_weights"), static_cast<GLsizei>(wf.size()), wf.data());
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Back into A, which the lit pass reads.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, blur_fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, moments_fbo_.id());
  const GLenum color = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &color);
  glBlitFramebuffer(0, 0, size_, size_, 0, 0, size_, size_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace shadowlab
