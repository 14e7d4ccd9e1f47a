// The bare minimum a shadowed frame costs: LearnOpenGL's shadow mapping (5.3.1.3) as two passes, a
// depth pass into a DEPTH24 map and a lit pass with PCF 3x3, its own two small programs and no lab
// machinery (no parameters, includes, skipping, G-buffer, timing). `shadowlab bench` draws it beside
// the lab's frame on the same scene, light and view, so the lab's overhead over the minimum is measured
// in every run.
#pragma once

#include <glm/glm.hpp>

#include "renderer/gl_objects.h"
#include "renderer/gpu_mesh.h"
#include "core/scene.h"

namespace shadowlab {

// LearnOpenGL's shadow-mapping scene: a 50 x 50 floor at y = -0.5 and three unit cubes (two at half
// size, one rotated 60 degrees at a quarter).
Scene make_learnopengl_scene();

class BareTwoPass {
 public:
  BareTwoPass(const Scene& scene, int map_size);  // needs a current GL context
  // Both passes, every frame (the tutorial redraws its map each frame): the depth map from
  // light_view_proj, then the scene lit by the directional light toward `to_light`, into `framebuffer`
  // (width x height, with a depth buffer).
  void draw(const glm::mat4& light_view_proj, const glm::vec3& to_light, const glm::mat4& camera_view_proj,
            GLuint framebuffer, int width, int height) const;

 private:
  GpuScene scene_;
  int map_size_;
  GlTexture depth_;
  GlFramebuffer fbo_;
  GlProgram depth_program_, lit_program_;
  GLint depth_mvp_ = -1, lit_vp_ = -1, lit_light_vp_ = -1, lit_to_light_ = -1, lit_map_ = -1;
};

}  // namespace shadowlab
