// glTF loading: base-colour images decoded once each (a checker where one cannot be), the textures and
// each primitive's material (core/gltf_loader.cpp).
#include "core/gltf_loader_parts.h"

#include <stb_image.h>

namespace shadowlab::gltf_detail {

constexpr int kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImagePixels = 64ull << 20;

bool decode_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
  auto& problems = static_cast<ImageProblems*>(user)->by_image;
  int w = 0, h = 0, channels = 0;
  if (!bytes || size <= 1 || !stbi_info_from_memory(bytes, size, &w, &h, &channels)) {
    problems[index] = size <= 1 ? "the image is empty"
                                : std::string("not an image stb_image can decode (") +
                                      (stbi_failure_reason() ? stbi_failure_reason() : "unknown format") + ")";
    return true;
  }
  if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide ||
      static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) > kMaxImagePixels) {
    problems[index] = "the image is " + std::to_string(w) + " x " + std::to_string(h) + " pixels, beyond the limit of " +
                      std::to_string(kMaxImageSide) + " a side and " + std::to_string(kMaxImagePixels) + " pixels";
    return true;
  }
  unsigned char* pixels = stbi_load_from_memory(bytes, size, &w, &h, &channels, 4);
  if (!pixels) {
    problems[index] = std::string("the image data is corrupt (") +
                      (stbi_failure_reason() ? stbi_failure_reason() : "unknown reason") + ")";
    return true;
  }
  image->width = w;
  image->height = h;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(pixels, pixels + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  stbi_image_free(pixels);
  return true;
}

// What replaces an image that could not be decoded: 8 x 8 magenta and black squares, seen at once.
std::shared_ptr<const std::vector<std::uint8_t>> checker_image(int* width, int* height) {
  constexpr int side = 64;
  auto rgba = std::make_shared<std::vector<std::uint8_t>>(side * side * 4);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const bool on = ((x / 8) + (y / 8)) % 2 == 0;
      std::uint8_t* p = rgba->data() + 4 * (y * side + x);
      p[0] = on ? 255 : 0;
      p[1] = 0;
      p[2] = on ? 255 : 0;
      p[3] = 255;
    }
  *width = *height = side;
  return rgba;
}

// One Texture per glTF texture; the pixels of an image are decoded once and shared by every texture
// that uses it. A bad or missing image becomes a checker, with one warning naming it and the problem.
std::vector<Texture> Loader::build_textures() {
  std::vector<Texture> out;
  std::map<int, Texture> images;  // per image: its pixels, or the checker and its problem
  for (std::size_t i = 0; i < model_.textures.size(); ++i) {
    const auto& gt = model_.textures[i];
    Texture t;
    if (gt.source >= 0) {
      auto found = images.find(gt.source);
      if (found == images.end()) {
        Texture img;
        const auto& gi = model_.images[static_cast<std::size_t>(gt.source)];
        img.name = !gi.uri.empty() && !gi.uri.starts_with("data:") ? printable(gi.uri, 200)
                                                                   : "image " + std::to_string(gt.source);
        if (const auto p = image_problems_.by_image.find(gt.source); p != image_problems_.by_image.end()) {
          img.problem = p->second;
        } else if (gi.image.empty() || gi.width <= 0 || gi.height <= 0) {
          img.problem = gi.uri.empty() || gi.uri.starts_with("data:") ? "the image data cannot be read"
                                                                       : "the file cannot be read (missing?)";
        } else {
          img.width = gi.width;
          img.height = gi.height;
          img.rgba = std::make_shared<const std::vector<std::uint8_t>>(gi.image);
        }
        if (!img.problem.empty()) {
          img.rgba = checker_image(&img.width, &img.height);
          warnings_.push_back("image " + std::to_string(gt.source) + " (" + img.name + "): " + img.problem +
                              "; drawn as a magenta checker");
        }
        found = images.emplace(gt.source, std::move(img)).first;
      }
      t = found->second;
    } else {
      t.name = "texture " + std::to_string(i) + " (no image)";
    }
    if (gt.sampler >= 0) {
      const auto& s = model_.samplers[static_cast<std::size_t>(gt.sampler)];
      t.wrap_s = s.wrapS;
      t.wrap_t = s.wrapT;
      if (s.minFilter > 0) t.min_filter = s.minFilter;
      if (s.magFilter > 0) t.mag_filter = s.magFilter;
    }
    out.push_back(std::move(t));
  }
  model_.images.clear();  // the pixels now live in the scene's textures
  return out;
}

// The primitive's material: base colour factor, texture (with its TEXCOORD_0), alpha mode and cutoff.
void Loader::apply_material(Mesh& mesh, int material, const tinygltf::Primitive& prim) const {
  if (material < 0) return;  // no material: the lab's grey, opaque
  const auto& mat = model_.materials[static_cast<std::size_t>(material)];
  const auto& factor = mat.pbrMetallicRoughness.baseColorFactor;
  if (factor.size() != 4 || !std::all_of(factor.begin(), factor.end(), [](double x) { return x >= 0.0 && x <= 1.0; }))
    fail("material " + std::to_string(material) + " baseColorFactor must be 4 numbers between 0 and 1");
  mesh.color = glm::vec3(static_cast<float>(factor[0]), static_cast<float>(factor[1]), static_cast<float>(factor[2]));
  mesh.alpha = static_cast<float>(factor[3]);
  if (mat.alphaMode == "MASK") mesh.alpha_mode = AlphaMode::Mask;
  else if (mat.alphaMode == "BLEND") mesh.alpha_mode = AlphaMode::Blend;
  mesh.alpha_cutoff = static_cast<float>(mat.alphaCutoff);
  const auto& info = mat.pbrMetallicRoughness.baseColorTexture;
  if (info.index < 0) return;
  const std::string set = "TEXCOORD_" + std::to_string(info.texCoord);
  const auto uv = prim.attributes.find(set);
  if (uv == prim.attributes.end()) {
    warnings_.push_back("material " + std::to_string(material) + "'s base colour texture reads " +
                                                   set + ", which the primitive does not have: drawn untextured");
    return;
  }
  mesh.uvs = read_floats<glm::vec2>(uv->second, set);
  mesh.texture = info.index;
}
}  // namespace shadowlab::gltf_detail
