// The billboards' cut-out: a tree on a quad, as an alpha per point of the quad (uv: (0, 0) bottom left,
// (1, 1) top right). A trunk, and a crown whose alpha falls from 1 inside to 0 at its rim, with round
// gaps between the leaves. The oracle evaluates the same function in C++ (billboard_alpha in
// renderer/billboards.cpp): keep the two equal.
const float kBillboardTau = 6.28318530718;

float billboard_alpha(vec2 uv) {
  float x = abs(uv.x - 0.5);
  float trunk = (x < 0.05 && uv.y < 0.4) ? 1.0 : 0.0;
  vec2 d = vec2(x / 0.45, (uv.y - 0.62) / 0.36);
  float crown = clamp(2.0 * (1.0 - length(d)), 0.0, 1.0);
  float leaves = 0.65 + 0.35 * cos(kBillboardTau * 5.0 * x) * cos(kBillboardTau * 5.0 * uv.y);
  return max(trunk, crown * leaves);
}
