// How steeply the light meets a surface: tan(angle of incidence) from n . l (0 < n_dot_l <= 1). Across
// one shadow-map texel the surface's depth changes by texel * tan(angle): what a slope-scaled bias
// multiplies. It grows without bound at grazing light; past MAX_TAN_INCIDENCE (tan 84 deg is about 10)
// the bias would lift whole shadows off their casters, so it stops there. (The shadow_ prefix keeps the
// name clear of what an exercise that includes "lab/bias.glsl" defines itself, e.g. tan_incidence.)
const float MAX_TAN_INCIDENCE = 10.0;

float shadow_tan_incidence(float n_dot_l) {
  return min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
}
