// Lab 10: procedural textures with gradient noise (the PGR lecture).
// Demonstrates: 2D gradient noise from a texture of gradients (the four corners' gradients dotted with
// the vectors from the corners to the point, blended with a smooth fade), the octave sum
// noise(p) + 0.5 noise(2p) + 0.25 noise(4p), and a pattern it perturbs: the floor that receives the
// shadows is wood (rings fract(rings |p|) through a smoothstep between the lecture's two browns), busy enough to hide
// some acne and aliasing and not others.
// Check: the student's functions run on chosen points (a probe, read back from a float target) and are
// compared with a CPU reference of the same definition on the same gradient texture: determinism,
// range, zero mean, zero at the lattice (gradient, not value noise), continuity across texel borders
// (no seams, no creases), no tiling within the period, the octaves' weights and the spectrum per band.
#include "grading/lab.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "grading/check.h"
#include "grading/probe.h"
#include "renderer/gl_objects.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/noise/gradient_noise.glsl";

// The gradient texture: kPeriod x kPeriod gradients at angles drawn from mt19937 with this seed (its
// raw output, which the C++ standard fixes), stored as RGBA8 (g * 0.5 + 0.5).
constexpr int kPeriod = 16;
// The wood's defaults (shaders/noise/wood.glsl; the README says why they are not the lecture's 10 rings per
// unit and 0.1 x noise added to the position).
constexpr double kDefaultRings = 3.0;       // rings per world unit
constexpr double kDefaultTurbulence = 0.8;  // rings the octave sum moves them
constexpr std::uint32_t kGradientSeed = 1910;
constexpr int kGridPerUnit = 16;                  // the spectrum grid: 16 samples per unit over one period
constexpr int kGrid = kPeriod * kGridPerUnit;     // 256 x 256 samples
constexpr int kRandomPoints = 4096;               // off the grid, in [-kRandomReach, kRandomReach]^2
constexpr double kRandomReach = 40.0;
constexpr int kBorderPoints = 2048;               // per axis, points on texel borders
constexpr double kBorderStep = 1.0 / 256.0;       // h: values at k - 2h, k - h, k + h, k + 2h
constexpr double kOctaveWeights[] = {1.0, 0.5, 0.25};
// Band edges in cycles per unit for the spectrum (octave bands).
constexpr double kBandEdges[] = {0.0, 0.5, 1.0, 2.0, 4.0, 8.0};

// The limits (measured: INSTRUCTOR.md, docs/measured/lab_10.json).
constexpr double kMaxNondeterminism = 0.0;    // bit for bit
constexpr double kMaxReferenceError = 0.001;   // float32 against double, the fade a choice of two
constexpr double kMaxAbsValue = 1.0;          // noise in [-1, 1]
constexpr double kMaxOctaveAbsValue = 1.75;   // 1 + 0.5 + 0.25
constexpr double kMaxMean = 0.05;             // the reference's mean over one period is 0 (3e-11 in float32)
constexpr double kMaxLatticeValue = 0.0001;     // gradient noise is 0 at every lattice point
constexpr double kMaxSeam = 0.05;             // |n(k + h) - n(k - h)|; the solution's largest is 0.0078
constexpr double kMaxCrease = 0.5;            // slope jump across a border; the solution's largest is 0.003
constexpr double kMaxTilingCorrelation = 0.5; // |correlation| of n(p) and n(p + s), 0 < s < period
constexpr double kMaxBandLog2Ratio = 0.5;     // energy per band within 0.71-1.41 x the reference's
constexpr double kMinBandShare = 1e-3;        // bands holding less of the reference's energy are not graded
constexpr double kMaxWeightError = 0.02;      // fitted octave weights against 1, 0.5, 0.25

struct Gradients {
  std::vector<std::uint8_t> rgba;  // kPeriod x kPeriod x 4
  std::vector<glm::dvec2> g;       // decoded as the shader does: byte / 255 * 2 - 1
};

const Gradients& gradients() {
  static const Gradients grads = [] {
    Gradients out;
    std::mt19937 rng(kGradientSeed);
    for (int i = 0; i < kPeriod * kPeriod; ++i) {
      const double angle = 2.0 * M_PI * (static_cast<double>(rng()) / 4294967296.0);
      const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround((v * 0.5 + 0.5) * 255.0)); };
      const std::uint8_t x = byte(std::cos(angle)), y = byte(std::sin(angle));
      out.rgba.insert(out.rgba.end(), {x, y, 128, 255});
      out.g.push_back({x / 255.0 * 2.0 - 1.0, y / 255.0 * 2.0 - 1.0});
    }
    return out;
  }();
  return grads;
}

// The CPU reference: the same definition in double. quintic: Perlin's 6t^5 - 15t^4 + 10t^3, else the
// cubic 3t^2 - 2t^3 (the lab's text allows either).
double reference_noise(glm::dvec2 p, bool quintic) {
  const auto& g = gradients().g;
  const glm::dvec2 i = glm::floor(p), f = p - i;
  const auto grad = [&](double x, double y) {
    const int gx = ((static_cast<int>(x) % kPeriod) + kPeriod) % kPeriod;
    const int gy = ((static_cast<int>(y) % kPeriod) + kPeriod) % kPeriod;
    return g[static_cast<std::size_t>(gy * kPeriod + gx)];
  };
  const auto fade = [&](double t) { return quintic ? t * t * t * (t * (t * 6 - 15) + 10) : t * t * (3 - 2 * t); };
  const double n00 = glm::dot(grad(i.x, i.y), f);
  const double n10 = glm::dot(grad(i.x + 1, i.y), f - glm::dvec2(1, 0));
  const double n01 = glm::dot(grad(i.x, i.y + 1), f - glm::dvec2(0, 1));
  const double n11 = glm::dot(grad(i.x + 1, i.y + 1), f - glm::dvec2(1, 1));
  const double u = fade(f.x), v = fade(f.y);
  return glm::mix(glm::mix(n00, n10, u), glm::mix(n01, n11, u), v);
}

double reference_octaves(glm::dvec2 p, bool quintic) {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) sum += kOctaveWeights[k] * reference_noise(p * static_cast<double>(1 << k), quintic);
  return sum;
}

// Energy per band (kBandEdges, cycles per unit) of a periodic kGrid x kGrid signal sampled kGridPerUnit
// per unit: a 2D DFT (separable, direct), the mean removed.
std::vector<double> band_energy(const std::vector<double>& signal) {
  const int n = kGrid;
  std::vector<std::complex<double>> twiddle(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) twiddle[static_cast<std::size_t>(k)] = std::polar(1.0, -2.0 * M_PI * k / n);
  double mean = 0.0;
  for (double v : signal) mean += v;
  mean /= static_cast<double>(signal.size());
  std::vector<std::complex<double>> rows(signal.size()), full(signal.size());
  const auto at = [n](int y, int x) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(n) + static_cast<std::size_t>(x); };
  for (int y = 0; y < n; ++y)
    for (int k = 0; k < n; ++k) {
      std::complex<double> s = 0.0;
      for (int x = 0; x < n; ++x) s += (signal[at(y, x)] - mean) * twiddle[static_cast<std::size_t>((k * x) % n)];
      rows[at(y, k)] = s;
    }
  for (int k = 0; k < n; ++k)
    for (int l = 0; l < n; ++l) {
      std::complex<double> s = 0.0;
      for (int y = 0; y < n; ++y) s += rows[at(y, k)] * twiddle[static_cast<std::size_t>((l * y) % n)];
      full[at(l, k)] = s;
    }
  std::vector<double> bands(std::size(kBandEdges) - 1, 0.0);
  for (int l = 0; l < n; ++l)
    for (int k = 0; k < n; ++k) {
      const int fk = k <= n / 2 ? k : k - n, fl = l <= n / 2 ? l : l - n;
      const double f = std::sqrt(double(fk * fk + fl * fl)) / kPeriod;  // cycles per unit
      for (std::size_t b = 0; b < bands.size(); ++b)
        if (f >= kBandEdges[b] && f < kBandEdges[b + 1]) bands[b] += std::norm(full[at(l, k)]);
    }
  return bands;
}

// The largest |log2| of the student's band energy over the reference's, over bands that hold at least
// kMinBandShare of the reference's energy.
double band_mismatch(const std::vector<double>& student, const std::vector<double>& reference) {
  double total = 0.0;
  for (double e : reference) total += e;
  double worst = 0.0;
  for (std::size_t b = 0; b < reference.size(); ++b) {
    if (reference[b] < kMinBandShare * total) continue;
    const double ratio = std::max(student[b], 1e-30) / reference[b];
    worst = std::max(worst, std::abs(std::log2(ratio)));
  }
  return worst;
}

// Largest |correlation| of a periodic grid signal with itself shifted by s whole units, 0 < s < period,
// along x, y and the diagonal.
double tiling_correlation(const std::vector<double>& signal) {
  const int n = kGrid;
  double mean = 0.0, var = 0.0;
  for (double v : signal) mean += v;
  mean /= static_cast<double>(signal.size());
  for (double v : signal) var += (v - mean) * (v - mean);
  if (var <= 0.0) return 0.0;
  double worst = 0.0;
  for (int s = 1; s < kPeriod; ++s)
    for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
      double c = 0.0;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const int x2 = (x + dx * s * kGridPerUnit) % n, y2 = (y + dy * s * kGridPerUnit) % n;
          c += (signal[static_cast<std::size_t>(y * n + x)] - mean) * (signal[static_cast<std::size_t>(y2 * n + x2)] - mean);
        }
      worst = std::max(worst, std::abs(c / var));
    }
  return worst;
}

GlTexture upload_gradients() {
  const auto& g = gradients();
  GlTexture t = make_texture_2d(GL_RGBA8, kPeriod, kPeriod, GL_RGBA, GL_UNSIGNED_BYTE, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kPeriod, kPeriod, GL_RGBA, GL_UNSIGNED_BYTE, g.rgba.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

constexpr int kLatticePoints = 1024;

// The cases the probe evaluates: in[i] = (p, which) with which 0 = gradient_noise, 1 = noise_octaves.
struct NoiseCases {
  std::vector<glm::vec4> in;
  std::vector<glm::dvec2> grid, random;  // the grid over one period; the random points off it
  // Where each part starts in `in`: the grid's noise at p, 2p, 4p and its octave sum; the random points'
  // noise and octave sum; the lattice points; the border points; the grid again, reversed.
  std::size_t g0 = 0, r0 = 0, l0 = 0, b0 = 0, d0 = 0;
};

NoiseCases noise_cases(std::uint32_t seed) {
  NoiseCases c;
  std::vector<glm::vec4>& in = c.in;
  const auto add = [&in](glm::dvec2 p, int which) {
    in.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(which), 0.0f});
  };
  // 1. The grid over one period: noise at p, 2p, 4p (the octaves fitted from the student's own noise)
  //    and the octave sum at p.
  for (int y = 0; y < kGrid; ++y)
    for (int x = 0; x < kGrid; ++x) c.grid.push_back(glm::dvec2(x, y) / static_cast<double>(kGridPerUnit));
  c.g0 = in.size();
  for (int k = 0; k < 3; ++k)
    for (const auto& p : c.grid) add(p * static_cast<double>(1 << k), 0);
  for (const auto& p : c.grid) add(p, 1);
  // 2. Random points off the grid, both functions.
  std::mt19937 rng(seed * 7919u + 10u);
  std::uniform_real_distribution<double> reach(-kRandomReach, kRandomReach);
  for (int i = 0; i < kRandomPoints; ++i) c.random.push_back({reach(rng), reach(rng)});
  c.r0 = in.size();
  for (const auto& p : c.random) add(p, 0);
  for (const auto& p : c.random) add(p, 1);
  // 3. Lattice points.
  std::uniform_int_distribution<int> lattice(-40, 40);
  c.l0 = in.size();
  for (int i = 0; i < kLatticePoints; ++i) add(glm::dvec2(lattice(rng), lattice(rng)), 0);
  // 4. Texel borders, crossing x = k and y = k: four points each.
  std::uniform_real_distribution<double> along(-20.0, 20.0);
  std::uniform_int_distribution<int> border(-20, 20);
  c.b0 = in.size();
  for (int axis = 0; axis < 2; ++axis)
    for (int i = 0; i < kBorderPoints; ++i) {
      const double k = border(rng), t = along(rng);
      for (double o : {-2.0, -1.0, 1.0, 2.0}) {
        const double a = k + o * kBorderStep;
        add(axis == 0 ? glm::dvec2(a, t) : glm::dvec2(t, a), 0);
      }
    }
  // 5. Determinism: the grid's noise again, in reverse order (another place in the target).
  c.d0 = in.size();
  for (std::size_t i = c.grid.size(); i-- > 0;) add(c.grid[i], 0);
  return c;
}

// The student's functions on the cases, with the gradient texture on unit 5.
std::vector<float> probe_noise(const Features& hooks, const std::vector<glm::vec4>& in) {
  GlTexture tex = upload_gradients();
  ProbeRequest request;
  request.fragment = "shaders/probe/noise.frag";
  request.in0 = in;
  request.passes.push_back([&tex](GLuint program) {
    glActiveTexture(GL_TEXTURE5);
    glBindTexture(GL_TEXTURE_2D, tex.id());
    set_uniform(program, "u_noise_gradients", 5);
    glActiveTexture(GL_TEXTURE0);
  });
  std::vector<float> v = run_probe(hooks, request).at(0);
  glActiveTexture(GL_TEXTURE5);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  return v;
}

// What the check measures of the probe's values.
struct NoiseFigures {
  double nondeterminism = 0.0;
  double err_noise[2] = {0, 0}, err_oct_ref[2] = {0, 0};  // against the reference, cubic and quintic fade
  bool quintic = false;
  double max_abs = 0.0, max_abs_oct = 0.0, mean = 0.0, lattice_max = 0.0, seam = 0.0, crease = 0.0;
  double tiling = 0.0, spectrum = 0.0, spectrum_oct = 0.0;
  std::vector<double> bands_student, bands_ref, bands_student_oct, bands_ref_oct;
  glm::dvec3 weights{0.0};
  double weight_error = 0.0, err_oct = 0.0;
};

// Determinism, the error against the reference (each fade), range, mean, lattice, seams and creases.
void measure_points(const NoiseCases& c, const std::vector<float>& v, NoiseFigures& f) {
  const auto value = [&v](std::size_t i) { return static_cast<double>(v[i]); };
  const std::size_t n = c.grid.size();
  const std::size_t g0 = c.g0, r0 = c.r0, l0 = c.l0, b0 = c.b0, d0 = c.d0;
  const std::vector<glm::dvec2>& grid = c.grid;
  const std::vector<glm::dvec2>& random = c.random;
  // Determinism.
  for (std::size_t i = 0; i < n; ++i)
    f.nondeterminism = std::max(f.nondeterminism, std::abs(value(g0 + i) - value(d0 + n - 1 - i)));
  // Against the reference, each fade; the better fits.
  for (int q = 0; q < 2; ++q) {
    for (std::size_t i = 0; i < n; ++i) {
      f.err_noise[q] = std::max(f.err_noise[q], std::abs(value(g0 + i) - reference_noise(grid[i], q == 1)));
      f.err_oct_ref[q] = std::max(f.err_oct_ref[q], std::abs(value(g0 + 3 * n + i) - reference_octaves(grid[i], q == 1)));
    }
    for (std::size_t i = 0; i < random.size(); ++i) {
      f.err_noise[q] = std::max(f.err_noise[q], std::abs(value(r0 + i) - reference_noise(random[i], q == 1)));
      f.err_oct_ref[q] =
          std::max(f.err_oct_ref[q], std::abs(value(r0 + random.size() + i) - reference_octaves(random[i], q == 1)));
    }
  }
  f.quintic = f.err_noise[1] < f.err_noise[0];
  // Range and mean of the noise (grid and random points), and of the octave sum.
  for (std::size_t i = 0; i < n; ++i) {
    f.max_abs = std::max(f.max_abs, std::abs(value(g0 + i)));
    f.max_abs_oct = std::max(f.max_abs_oct, std::abs(value(g0 + 3 * n + i)));
    f.mean += value(g0 + i);
  }
  for (std::size_t i = 0; i < random.size(); ++i) {
    f.max_abs = std::max(f.max_abs, std::abs(value(r0 + i)));
    f.max_abs_oct = std::max(f.max_abs_oct, std::abs(value(r0 + random.size() + i)));
  }
  f.mean /= static_cast<double>(n);
  for (int i = 0; i < kLatticePoints; ++i) f.lattice_max = std::max(f.lattice_max, std::abs(value(l0 + static_cast<std::size_t>(i))));
  // Seams (value jumps) and creases (slope jumps) across texel borders.
  for (std::size_t i = 0; i < 2 * static_cast<std::size_t>(kBorderPoints); ++i) {
    const double a = value(b0 + 4 * i), b = value(b0 + 4 * i + 1), c = value(b0 + 4 * i + 2), d = value(b0 + 4 * i + 3);
    f.seam = std::max(f.seam, std::abs(c - b));
    f.crease = std::max(f.crease, std::abs((d - c) - (b - a)) / kBorderStep);
  }
}

// Tiling and spectrum on the grid; the octave weights fitted on the student's own noise.
void measure_grid(const NoiseCases& c, const std::vector<float>& v, NoiseFigures& f) {
  const auto value = [&v](std::size_t i) { return static_cast<double>(v[i]); };
  const std::size_t n = c.grid.size();
  const std::size_t g0 = c.g0;
  const std::vector<glm::dvec2>& grid = c.grid;
  // Tiling and spectrum on the grid.
  std::vector<double> student_noise(n), student_oct(n), ref_noise(n), ref_oct(n);
  for (std::size_t i = 0; i < n; ++i) {
    student_noise[i] = value(g0 + i);
    student_oct[i] = value(g0 + 3 * n + i);
    ref_noise[i] = reference_noise(grid[i], f.quintic);
    ref_oct[i] = reference_octaves(grid[i], f.quintic);
  }
  f.tiling = tiling_correlation(student_noise);
  f.bands_student = band_energy(student_noise);
  f.bands_ref = band_energy(ref_noise);
  f.bands_student_oct = band_energy(student_oct);
  f.bands_ref_oct = band_energy(ref_oct);
  f.spectrum = band_mismatch(f.bands_student, f.bands_ref);
  f.spectrum_oct = band_mismatch(f.bands_student_oct, f.bands_ref_oct);
  // The octave weights: least squares of the sum on the student's own noise at p, 2p, 4p.
  double ata[3][3] = {}, atb[3] = {};
  for (std::size_t i = 0; i < n; ++i) {
    const double x[3] = {value(g0 + i), value(g0 + n + i), value(g0 + 2 * n + i)};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) ata[r][c] += x[r] * x[c];
      atb[r] += x[r] * value(g0 + 3 * n + i);
    }
  }
  glm::dmat3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[c][r] = ata[r][c];
  if (std::abs(glm::determinant(m)) > 1e-12) f.weights = glm::inverse(m) * glm::dvec3(atb[0], atb[1], atb[2]);
  for (int k = 0; k < 3; ++k) f.weight_error = std::max(f.weight_error, std::abs(f.weights[k] - kOctaveWeights[k]));
  if (!std::isfinite(f.weight_error)) f.weight_error = 1e30;
  // The octave sum against the student's own noise at p, 2p, 4p (each part graded on its own).
  for (std::size_t i = 0; i < n; ++i)
    f.err_oct = std::max(f.err_oct, std::abs(value(g0 + 3 * n + i) -
                                             (value(g0 + i) + 0.5 * value(g0 + n + i) + 0.25 * value(g0 + 2 * n + i))));
}

// The conditions and metrics the check records, and its two lines of figures.
void report_noise(std::uint32_t seed, std::size_t cases, const NoiseFigures& f, CheckResult& result) {
  nlohmann::json& metrics = result.metrics;
  // The held-out part: the off-grid, lattice and border points are drawn from the seed.
  result.conditions.push_back({{"tag", "points"}, {"seed", seed}, {"off_grid", kRandomPoints},
                               {"reach", kRandomReach}, {"lattice", kLatticePoints}, {"borders", 2 * kBorderPoints}});
  metrics["gradients"] = {{"size", kPeriod}, {"seed", kGradientSeed}, {"format", "RGBA8, g * 0.5 + 0.5"}};
  metrics["cases"] = cases;
  metrics["fade"] = f.quintic ? "quintic" : "cubic";
  metrics["reference_error"] = {{"cubic", f.err_noise[0]}, {"quintic", f.err_noise[1]}};
  metrics["octaves_reference_error"] = {{"cubic", f.err_oct_ref[0]}, {"quintic", f.err_oct_ref[1]}};
  metrics["octave_weights"] = {f.weights[0], f.weights[1], f.weights[2]};
  metrics["band_edges"] = kBandEdges;
  metrics["band_energy"] = {{"noise", f.bands_student}, {"noise_reference", f.bands_ref}, {"octaves", f.bands_student_oct},
                            {"octaves_reference", f.bands_ref_oct}};
  std::printf("    noise: fade %s, error %.2e, |max| %.3f, mean %.4f, lattice %.1e, seam %.4f, crease %.3f, tiling %.3f, "
              "spectrum %.3f\n",
              f.quintic ? "quintic" : "cubic", std::min(f.err_noise[0], f.err_noise[1]), f.max_abs, f.mean, f.lattice_max, f.seam, f.crease,
              f.tiling, f.spectrum);
  std::printf("    octaves: weights %.4f %.4f %.4f, error %.2e, |max| %.3f, spectrum %.3f\n", f.weights[0], f.weights[1],
              f.weights[2], f.err_oct, f.max_abs_oct, f.spectrum_oct);
}

void noise_criteria(const NoiseFigures& f, CheckResult& result) {
  const std::string why = "probe: the student's function on chosen points against a CPU reference of the same definition";
  auto& c = result.criteria;
  c.push_back({"noise.deterministic", f.nondeterminism, Criterion::kAtMost, kMaxNondeterminism,
               "the same points drawn twice at other places of the target give the same values",
               "the noise must depend on p only (no gl_FragCoord, time or counters)."});
  c.push_back({"noise.matches_reference", std::min(f.err_noise[0], f.err_noise[1]), Criterion::kAtMost, kMaxReferenceError, why,
               "compute the gradient noise as the text defines it: the four corners' gradients from the texture, "
               "dotted with the vectors from the corners to p, blended with a fade."});
  c.push_back({"noise.range", f.max_abs, Criterion::kAtMost, kMaxAbsValue, "gradient noise stays in [-1, 1]",
               "decode the gradients to [-1, 1] (times 2, minus 1) and return the blend itself, not a remapped value."});
  c.push_back({"noise.mean", std::abs(f.mean), Criterion::kAtMost, kMaxMean,
               "over one whole period gradient noise averages to exactly 0 (each corner's ramp cancels over its cells)",
               "noise must average to zero: return the signed blend, not 0.5 + 0.5 n."});
  c.push_back({"noise.zero_at_lattice", f.lattice_max, Criterion::kAtMost, kMaxLatticeValue,
               "gradient noise is 0 at every lattice point (the vector from the corner is 0 there)",
               "this is value noise: blend dot(gradient, p - corner), not a random value per corner."});
  c.push_back({"noise.seam", f.seam, Criterion::kAtMost, kMaxSeam,
               "the jump between values 2/256 apart across a texel border (the solution's largest: 0.0078)",
               "each corner's vector is p minus that corner (f, f - (1,0), f - (0,1), f - (1,1))."});
  c.push_back({"noise.crease", f.crease, Criterion::kAtMost, kMaxCrease,
               "the change of slope across a texel border; the fade has zero slope at 0 and 1",
               "blend with a fade (3t^2 - 2t^3 or 6t^5 - 15t^4 + 10t^3), not with t itself: linear blending "
               "leaves creases along the texel borders."});
  c.push_back({"noise.tiles_early", f.tiling, Criterion::kAtMost, kMaxTilingCorrelation,
               "correlation of the noise with itself shifted by 1-15 units; it repeats only every 16",
               "look up corner i's gradient at texel i of the whole texture, (i + 0.5) / N with N its size."});
  c.push_back({"noise.spectrum", f.spectrum, Criterion::kAtMost, kMaxBandLog2Ratio,
               "energy per octave band (0-0.5-1-2-4-8 cycles per unit) within 0.71-1.41 x the reference's"});
  c.push_back({"octaves.weights", f.weight_error, Criterion::kAtMost, kMaxWeightError,
               "the sum's weights fitted on the noise at p, 2p and 4p, against 1, 0.5, 0.25",
               "sum three octaves, noise(p) + 0.5 noise(2p) + 0.25 noise(4p): each doubles the frequency and "
               "halves the amplitude."});
  c.push_back({"octaves.matches_reference", f.err_oct, Criterion::kAtMost, kMaxReferenceError,
               "the sum against noise(p) + 0.5 noise(2p) + 0.25 noise(4p) of your own noise"});
  c.push_back({"octaves.range", f.max_abs_oct, Criterion::kAtMost, kMaxOctaveAbsValue, "at most 1 + 0.5 + 0.25"});
  c.push_back({"octaves.spectrum", f.spectrum_oct, Criterion::kAtMost, kMaxBandLog2Ratio,
               "energy per octave band within 0.71-1.41 x the reference octave sum's"});
}

void check_noise(CheckContext& ctx, CheckResult& result) {
  const Features hooks = ctx.hooks();
  ctx.use(hooks);  // the wood floor's programs build with the student's file
  const NoiseCases cases = noise_cases(ctx.seed);
  const std::vector<float> v = probe_noise(hooks, cases.in);
  NoiseFigures f;
  measure_points(cases, v, f);
  measure_grid(cases, v, f);
  report_noise(ctx.seed, cases.in.size(), f, result);
  noise_criteria(f, result);
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Procedural noise: gradient noise and wood";
  lab.summary = "Gradient noise from a texture of gradients, three octaves, and a wood floor under the shadows.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = {
      {"noise.view", "Floor view", ParamKind::Choice, 0, 0, 3,
       "What the floor shows: the wood, the noise, the octave sum, or the three octaves as red, green, blue.",
       {"wood", "noise", "octave sum", "octaves (RGB)"}},
      {"noise.scale", "Noise scale", ParamKind::Float, 1.5, 0.25, 8.0,
       "Noise units (gradient texels) per world unit on the floor.", {}},
      {"noise.rings", "Rings per unit", ParamKind::Float, kDefaultRings, 1.0, 40.0, "The wood's rings per world unit.", {}},
      {"noise.turbulence", "Turbulence", ParamKind::Float, kDefaultTurbulence, 0.0, 6.0,
       "How far the octave sum pushes the rings, in rings.", {}},
  };
  // In the window a preset first puts every key some preset sets back to the lab's value (show_preset):
  // "slope bias on wood" sets acne on wood's grazing light and small bias itself, so that it is the same
  // picture with the slope bias alone added, as README.md says.
  lab.presets = {
      {"wood", "The wood floor with its shadows.", {{"noise.view", "wood"}}},
      {"noise", "One octave of gradient noise on the floor.", {{"noise.view", "noise"}}},
      {"octaves", "The octave sum; then the octaves apart in red, green, blue.", {{"noise.view", "octave sum"}}},
      {"plain rings", "No turbulence: the rings alone.", {{"noise.view", "wood"}, {"noise.turbulence", "0"}}},
      {"acne on wood", "Lab 1's acne under a grazing light, on the busy floor.",
       {{"noise.view", "wood"}, {"light.elevation", "8"}, {"shadow.bias", "0.0005"}, {"shadow.slope_bias", "0"},
        {"noise.turbulence", "0.8"}},
       {.provokes = "acne", .fixed_by = "slope bias on wood"}},
      {"slope bias on wood", "The same grazing light with lab 1's slope-scaled bias: the stripes go, the rings stay.",
       {{"noise.view", "wood"}, {"shadow.slope_bias", "2"}, {"light.elevation", "8"}, {"shadow.bias", "0.0005"},
        {"noise.turbulence", "0.8"}}},
  };
  lab.offered_includes = {};
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.includes["lab/noise.glsl"] = files.at(0).string();
    hooks.includes["lab/material.glsl"] = "shaders/noise/wood.glsl";
    const auto& g = gradients();
    hooks.material_textures["u_noise_gradients"] = {kPeriod, kPeriod, g.rgba};
    hooks.material_params = {{"u_noise_view", "noise.view"},
                             {"u_noise_scale", "noise.scale"},
                             {"u_wood_rings", "noise.rings"},
                             {"u_wood_turbulence", "noise.turbulence"}};
    return hooks;
  };
  lab.check = check_noise;
  return lab;
}

}  // namespace shadowlab
