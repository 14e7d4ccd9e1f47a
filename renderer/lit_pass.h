// The lit pass: the scene from the camera, ambient + Lambert, the light's term scaled by the shadow
// technique's visibility ("lab/visibility.glsl"). It owns the view's render targets (colour, depth or
// depth-stencil, and the G-buffer a check reads: visibility, world positions, normals) and the lit
// programs, one per variant the shadow pass asks for (see LitVariant), built with the technique's
// includes and the light type's defines. Each variant is built generic (every uniform a uniform: what
// set_features builds and reports errors from) and, when first drawn with constants (the technique's
// settings, ShadowPass::lit_constants and ShadowTest::constants), compiled once more with them as constants: the program a frame
// draws with is the one for exactly those settings. A specialisation that fails to build (none should:
// it only turns uniforms into constants) is not retried and the generic program draws instead.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <memory>
#include <utility>
#include <vector>

#include "oracle/oracle.h"
#include "renderer/shadow_pass.h"

namespace shadowlab {

class LitPass {
 public:
  // Builds the variants a technique's shape asks for (plain and G-buffer; the overlay with the shape's
  // shader; with `lights` > 0 the lit one lit by that many
  // shadowed lights too: the SHADOWED_LIGHTS define, Features::lights; with `own_shadow_coords`, those whose
  // shadow test is the lab's, without the renderer's mapping into the shadow map: see
  // Features::own_shadow_coords); false keeps the old programs (the error is in them). Programs of other
  // variants stay until keep_only().
  bool build(const IncludeMap& includes, const IncludeRules& rules, LightType light, const ShadowPass::Shape& shape,
             int lights = 0, bool own_shadow_coords = false);
  void keep_only(const std::vector<LitVariant>& variants);
  // Compiles the material variant (MATERIAL_TEXTURE: base-colour texture, alpha modes) or the plain
  // one into every program; draw() switches to what the scene needs, so a scene without textures or
  // alpha modes draws with exactly the plain program.
  void use_materials(bool on);
  void for_each_program(const std::function<void(ReloadableProgram&)>& f);

  // The view's targets for this size; with `stencil` a DEPTH24_STENCIL8 depth buffer (shadow volumes),
  // with `gbuffer` the G-buffer attachments too. With `to_window` the view is drawn straight into the
  // window's framebuffer (0, which has depth and stencil): no target of its own, no copy; read-backs
  // and present() then have nothing of their own to read.
  void ensure_targets(int width, int height, bool gbuffer, bool stencil, bool to_window = false, GLuint window = 0);
  // The material's textures and parameter uniforms (Features::material_textures, material_params),
  // bound by every draw.
  void set_material(const std::map<std::string, MaterialTexture>& textures,
                    const std::map<std::string, std::string>& params);
  // The constants the next draws compile in (empty, or with specialise off: the generic programs).
  void use_constants(const LitConstants& constants) { constants_ = constants; }
  void set_specialise(bool on) { specialise_ = on; }
  // Whose begin_additive_lit_pass sets the shadow volumes' additive pass (Features::gl_host).
  void set_host_code(const GlHostCode& code) { code_ = code; }
  // Draws the scene with a variant's program, binding what the frame's lit inputs name
  // (ctx.lit_inputs: the shadow pass's map and the shadow test's uniforms).
  void draw(PassContext& ctx, LitVariant variant);
  // The constants the last draw's program was compiled with (empty: the generic program).
  const LitConstants& drawn_constants() const { return drawn_constants_; }

  GLuint framebuffer() const { return to_window_ ? window_ : fbo_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }

  // Read-backs of the last frame: colour RGBA8 top row first; the others bottom row first (GL order).
  std::vector<std::uint8_t> read_color() const;
  std::vector<float> read_visibility() const;
  GBuffer read_gbuffer() const;
  // Copies the colour onto another framebuffer (0: the window), scaled to its size.
  void present(GLuint framebuffer, int width, int height) const;

 private:
  GlHostCode code_;
  struct Program {
    ReloadableProgram program;
    LitUniforms u;
    const ShadowTest* test = nullptr;  // whose uniforms test_bind sets (looked up on this program)
    ShadowTestBind test_bind;
    std::uint64_t pass_serial = 0;  // the technique pass whose pass_bind this is (ShadowPass::serial)
    LitBind pass_bind;
  };
  struct Slot {
    Program generic;
    std::vector<std::pair<LitConstants, std::unique_ptr<Program>>> specialised;
    // Specialisations that did not build from the generic program's generation: the generic one draws.
    std::vector<std::pair<LitConstants, int>> failed;
  };
  using Key = std::pair<LitVariant, bool>;  // variant, G-buffer
  Program& program_for(Slot& slot);
  void begin(LitVariant variant, bool gbuffer, bool default_framebuffer) const;
  static void end();
  void set_uniforms(const PassContext& ctx, const Program& p) const;

  void bind_material(const ReloadableProgram& program, const PassContext& ctx) const;

  std::map<Key, Slot> programs_;
  std::vector<std::pair<std::string, GlTexture>> material_textures_;
  std::map<std::string, std::string> material_params_;
  // Per program id: the generation its material locations were looked up for, and the locations.
  mutable std::map<GLuint, std::pair<int, std::vector<GLint>>> material_locations_;
  LitConstants constants_, drawn_constants_;
  bool specialise_ = true;
  bool materials_ = false;
  int width_ = 0, height_ = 0;
  bool gbuffer_ = false;
  bool stencil_ = false;
  bool to_window_ = false;
  GLuint window_ = 0;  // with to_window_: where the view is drawn (0: the window's framebuffer)
  GlTexture color_, visibility_, position_, normal_;
  GlRenderbuffer depth_;
  GlFramebuffer fbo_;
};

}  // namespace shadowlab
