#include "app/imgui_offscreen.h"

#include <cstdio>
#include <stdexcept>

#include "app/imgui_gl.h"
#include "renderer/gl.h"
#include "renderer/gl_objects.h"
#include "core/image_io.h"
#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace shadowlab {

ImGuiOffscreen::ImGuiOffscreen(int width, int height)
    : width_(width), height_(height), previous_context_(ImGui::GetCurrentContext()) {
  ImGuiContext* ctx = ImGui::CreateContext();
  context_ = ctx;
  ImGui::SetCurrentContext(ctx);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.0f / 60.0f;  // no platform backend: time and size are ours to set
  ImGui::StyleColorsDark();
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) throw std::runtime_error("ImGui's OpenGL3 backend failed to start");
}

ImGuiOffscreen::~ImGuiOffscreen() {
  ImGui::SetCurrentContext(static_cast<ImGuiContext*>(context_));
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(static_cast<ImGuiContext*>(context_));
  ImGui::SetCurrentContext(static_cast<ImGuiContext*>(previous_context_));
}

UiFonts ImGuiOffscreen::use_fonts(const std::filesystem::path& folder, const UiScale& scale) {
  ImGui::SetCurrentContext(static_cast<ImGuiContext*>(context_));
  std::string warning;
  UiFonts fonts = build_ui_fonts(*ImGui::GetIO().Fonts, folder, scale.raster, &warning);
  if (!warning.empty()) std::fprintf(stderr, "shadowlab: warning: %s\n", warning.c_str());
  drop_font_texture();  // made again, from the new atlas, by the next NewFrame
  apply_ui_style(scale);
  return fonts;
}

std::vector<std::uint8_t> ImGuiOffscreen::render(const std::function<void()>& draw,
                                                  const std::vector<std::uint8_t>* background) {
  ImGui::SetCurrentContext(static_cast<ImGuiContext*>(context_));
  GlTexture color = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, color.id());
  std::vector<std::uint8_t> pixels;
  if (background) {
    pixels = *background;
    flip_rows(pixels, width_, height_, 4);  // GL rows start at the bottom
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, background ? pixels.data() : nullptr);
  GlFramebuffer fbo = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("ImGui offscreen framebuffer is incomplete");
  glViewport(0, 0, width_, height_);
  if (!background) {
    glClearColor(0.10f, 0.11f, 0.13f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  // Three frames: the first lays windows out, auto-sized windows settle on the second.
  for (int frame = 0; frame < 3; ++frame) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    draw();
    ImGui::Render();
  }
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  pixels.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  flip_rows(pixels, width_, height_, 4);
  for (std::size_t i = 3; i < pixels.size(); i += 4) pixels[i] = 255;  // a PNG without holes
  return pixels;
}

}  // namespace shadowlab
