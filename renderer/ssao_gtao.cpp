// The AO pass's second method, GTAO (renderer/ssao_pass.h, shaders/ssao/gtao.frag): the AO buffer from the
// same view-space G-buffer and noise as SSAO's, into the same target, so that the blur, the composite and
// the debug quads serve both.
#include "renderer/ssao_pass.h"

#include "core/ao_params.h"

namespace shadowlab {

void SsaoPass::draw_gtao(PassContext& ctx) {
  const ParamSet& params = ctx.params;
  glBindFramebuffer(GL_FRAMEBUFFER, open_fbo_.id());
  glViewport(0, 0, width_, height_);
  glUseProgram(gtao_.id());
  const GtaoUniforms& u = gtao_u_.get(gtao_, [](GLuint id) {
    return GtaoUniforms{{id, "u_position"},   {id, "u_normal"},     {id, "u_noise"},
                        {id, "u_noise_scale"}, {id, "u_use_noise"}, {id, "u_projection"},
                        {id, "u_directions"},  {id, "u_steps"},     {id, "u_radius"}};
  });
  const GLuint textures[3] = {position_.id(), normal_.id(), noise_.id()};
  const Uniform* samplers[3] = {&u.position, &u.normal, &u.noise};
  for (int unit = 0; unit < 3; ++unit) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, textures[unit]);
    samplers[unit]->set(unit);
  }
  u.noise_scale.set(glm::vec2(static_cast<float>(width_), static_cast<float>(height_)) / static_cast<float>(kSsaoNoiseSide));
  u.use_noise.set(params.get(param::ssao_noise) ? 1 : 0);
  u.projection.set(ctx.camera_projection);
  u.directions.set(params.get(param::ssao_gtao_directions));
  u.steps.set(params.get(param::ssao_gtao_steps));
  u.radius.set(params.get(param::ssao_radius));
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace shadowlab
