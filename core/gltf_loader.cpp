// glTF 2.0 loading. tinygltf parses the JSON/GLB and the buffers; everything it hands back is checked
// here before use, because tinygltf 2.7.0 accepts out-of-range indices, accessors running past their
// buffers, node loops and the like without a word.
//
// The order of the checks matters:
//   1. the file itself (a regular file, its size limit before reading, GLB version and chunks); its
//      JSON measured (depth, values, array sizes) and type-checked against the glTF 2.0 schema, the
//      buffers' declared sizes summed against the scene's budget; then tinygltf, whose file reads go
//      through a sandbox that opens files only inside the model's folder, relative to its handle;
//   2. every index reference in the document, buffer views against their buffers, accessor layouts;
//   3. the node hierarchy (one parent per node, no loops, depth limit, finite transforms);
//   4. the scene walk, which lists the triangle primitives to draw and checks their formats, the
//      instances and the declared vertex/triangle totals against LoadLimits, before anything is
//      allocated for them;
//   5. accessor byte ranges against their buffer views (after 4, so that a file declaring billions of
//      vertices is refused for the limit it breaks, whatever else is wrong with it);
//   6. reading: positions must be finite, indices in range, world positions within max_coordinate;
//      normals are used when they are sound.
#include "core/gltf_loader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/transform.hpp>
#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <tiny_gltf.h>

#include "core/gltf_schema.h"
#include "core/platform.h"
#include "core/untrusted.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

// glTF buffers are little-endian; elements are copied out byte for byte.
static_assert(std::endian::native == std::endian::little, "the glTF reader assumes a little-endian host");

constexpr std::uint64_t kMaxU64 = std::numeric_limits<std::uint64_t>::max();

// a * b + c, or nothing when it does not fit in 64 bits.
std::optional<std::uint64_t> mul_add(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  if (b != 0 && a > (kMaxU64 - c) / b) return std::nullopt;
  return a * b + c;
}

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) { return b > kMaxU64 - a ? kMaxU64 : a + b; }

std::string str(std::uint64_t n) { return std::to_string(n); }

// ---------------------------------------------------------------------------------------------------
// The file sandbox. tinygltf resolves a buffer or image URI by url-decoding it, joining it to the base
// folder we give it ("<base>/<uri>", even when the URI is absolute) and calling FileExists, then
// ReadWholeFile on the first candidate that exists. It also tries "./<uri>" (the working directory),
// which is never allowed. So the callbacks recover the URI from the joined path and judge the URI;
// FileExists only looks at the URI's text, and ReadWholeFile opens the file once, relative to the
// model's folder's handle (platform::Folder: no link followed out of it, nothing looked up twice).

// tinygltf's dlib::urldecode, which it applies to buffer and image URIs before looking for them: '+'
// becomes a space, %XY a byte. The same decoding here matches the URIs tinygltf asks for to the
// buffers that declared them.
std::string url_decode(const std::string& uri) {
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;
  };
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += static_cast<char>(hex(uri[i + 1]) << 4 | hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

struct FolderSandbox {
  explicit FolderSandbox(const fs::path& folder) : base_dir(folder.string()), folder(folder) {}

  std::string base_dir;      // the model's folder, absolute, exactly as handed to tinygltf
  platform::Folder folder;   // the same folder, opened once
  // Decoded URIs of external buffers and the largest byteLength declared for each: a file larger than
  // what its buffer declares is refused before it is read.
  std::map<std::string, std::uint64_t> buffer_uris;
  std::string problem;  // the first refusal; load_gltf reports it once tinygltf returns

  // The URI tinygltf joined to base_dir to make `path`, or nothing for any other path.
  std::optional<std::string> uri_of(const std::string& path) const {
    const std::string prefix = base_dir.ends_with('/') ? base_dir : base_dir + '/';
    if (!path.starts_with(prefix)) return std::nullopt;
    return path.substr(prefix.size());
  }

  // Why the text of `uri` is refused, or an empty string when the folder may be asked for it.
  static std::string refusal(const std::string& uri) {
    if (uri.find('\0') != std::string::npos) return "it contains a NUL character";
    // A ':' ahead of the first '/' makes a scheme (RFC 3986: a relative path whose first segment holds
    // a ':' must be written "./a:b"); this also catches drive letters ("C:/...") and an empty scheme.
    const std::size_t colon = uri.find(':');
    if (colon != std::string::npos && colon < uri.find('/'))
      return "scheme " + quote(uri.substr(0, colon + 1), 32) +
             " is not allowed; only relative paths inside the model's folder and data: URIs are";
    if (uri.starts_with('/') || uri.starts_with('\\')) return "absolute paths are not allowed";
    return {};
  }

  void refuse(const std::string& uri, const std::string& why) {
    if (problem.empty()) problem = "URI " + quote(uri) + " refused: " + why;
  }
};

constexpr std::uint64_t kMaxImageFileBytes = 64ull << 20;

bool sandbox_file_exists(const std::string& path, void* user) {
  auto& box = *static_cast<FolderSandbox*>(user);
  const auto uri = box.uri_of(path);
  // The working-directory retry, a buffer without a URI, or a data: URI tinygltf could not decode
  // (malformed, or a MIME type it does not know): nothing to look for; tinygltf reports "File not
  // found" for a buffer and only warns for an image, which we do not use anyway.
  if (!uri || uri->empty() || uri->starts_with("data:")) return false;
  if (const std::string why = FolderSandbox::refusal(*uri); !why.empty()) {
    box.refuse(*uri, why);
    return false;
  }
  return true;  // ReadWholeFile opens it, once, and says what is wrong with it
}

std::string sandbox_expand_path(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool sandbox_read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto& box = *static_cast<FolderSandbox*>(user);
  const auto uri = box.uri_of(path);
  if (!uri || uri->empty()) {
    *err = "only files inside the model's folder may be read";
    return false;
  }
  if (const std::string why = FolderSandbox::refusal(*uri); !why.empty()) {
    box.refuse(*uri, why);
    *err = why;
    return false;
  }
  // A buffer is read up to the byteLength it declares; an image up to kMaxImageFileBytes (decoded once,
  // by decode_image).
  const auto buffer = box.buffer_uris.find(*uri);
  const bool is_buffer = buffer != box.buffer_uris.end();
  try {
    const std::string bytes = box.folder.read(*uri, is_buffer ? buffer->second : kMaxImageFileBytes);
    out->assign(bytes.begin(), bytes.end());
    if (!is_buffer && out->empty()) out->assign(1, 0);  // an empty image file: decode_image says so
    return true;
  } catch (const platform::FileError& e) {
    *err = printable(e.what());
    if (e.problem() == platform::FileProblem::Outside) {
      box.refuse(*uri, e.what());
    } else if (is_buffer && box.problem.empty()) {
      box.problem = "buffer URI " + quote(*uri) + ": " +
                    (e.problem() == platform::FileProblem::TooLarge
                         ? "the file " + std::string(e.what()) + " (the byteLength its buffer declares)"
                         : std::string(e.what()));
    }
    return false;  // an image that cannot be read is only a warning, as tinygltf has it
  }
}

// Base-colour images are decoded here, once each, to RGBA8. One that cannot be decoded (corrupt, an
// unknown format, too large) is not an error of the model: its problem is kept per image, the loader
// reports it and draws a checker in its place.
struct ImageProblems {
  std::map<int, std::string> by_image;
};
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

// ---------------------------------------------------------------------------------------------------

std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // INT, DOUBLE and anything else: not allowed in glTF 2.0 accessors
  }
}

const char* component_name(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "an invalid component type";
  }
}

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    default: return "MAT4";  // tinygltf rejects any other type while parsing
  }
}

// Bytes of one element; for the formats we read (VEC3 FLOAT, SCALAR integers) there is no padding.
std::size_t element_size(const tinygltf::Accessor& a) {
  return component_size(a.componentType) *
         static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)));
}

bool all_finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// One triangle primitive of one node instance, found by the scene walk and drawn as one Mesh.
struct Draw {
  int node = 0, mesh = 0, primitive = 0;
  glm::dmat4 world{1.0};
};

class Loader {
 public:
  Loader(const fs::path& path, const LoadLimits& limits) : path_(path), limits_(limits) {}

  Scene load() {
    parse();
    check_asset();
    check_references();
    name_accessor_roles();
    check_buffer_views();
    check_accessor_layouts();
    check_nodes();
    const std::vector<Draw> draws = walk_scene();
    check_accessor_ranges();

    Scene scene;
    scene.name = printable(path_.string(), 400);
    scene.textures = build_textures();
    scene.meshes.reserve(draws.size());
    for (const Draw& d : draws) scene.meshes.push_back(build_mesh(d));
    if (scene.meshes.empty()) fail("no triangle meshes to draw");
    // World positions in double; the float vertices relative to the scene's origin (core/placement.h).
    scene.origin = far_origin(scene.meshes, draws);
    for (std::size_t i = 0; i < draws.size(); ++i) place_mesh(scene.meshes[i], draws[i], scene.origin);
    return scene;
  }

  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  // One printable line of bounded length: the parts quoted from the file were cut already, this bounds
  // the whole (and escapes a file name that holds control characters).
  [[noreturn]] void fail(const std::string& problem) const {
    throw LoadError(printable(path_.string(), 400) + ": " + printable(problem, 1200));
  }

  // ---- 1. The file and tinygltf.

  // Debian's tinygltf trusts a GLB chunk's declared length: a BIN chunk that claims more bytes than the
  // file holds makes it copy past the end of the input (found by the fuzzer). Every chunk must fit in
  // the file before tinygltf sees it; other container faults (lengths, headers) are left to its parser.
  // Returns the JSON chunk (the first chunk, when its type is JSON), for the checks before tinygltf.
  std::string_view check_glb_chunks(std::string_view bytes) {
    auto u32 = [&](std::uint64_t at) {
      std::uint32_t v = 0;
      std::memcpy(&v, bytes.data() + at, 4);
      return v;
    };
    const std::uint64_t end = bytes.size();  // a wrong header length is the parser's to report
    std::uint64_t at = 12;
    std::string_view json;
    for (int chunk = 0; at + 8 <= end; ++chunk) {
      const std::uint64_t length = u32(at);
      char type[5] = {};
      std::memcpy(type, bytes.data() + at + 4, 4);
      for (char& c : type)
        if (c != 0 && !std::isprint(static_cast<unsigned char>(c))) c = '?';
      if (at + 8 + length > end)
        fail("GLB container: chunk " + str(chunk) + " (" + type + ") declares " + str(length) + " bytes, but only " +
             str(end - at - 8) + " remain in the file");
      if (chunk == 0 && std::memcmp(bytes.data() + at + 4, "JSON", 4) == 0)
        json = bytes.substr(static_cast<std::size_t>(at + 8), static_cast<std::size_t>(length));
      at += 8 + length;
    }
    return json;
  }

  // The model file, read once: a FIFO, a device or a folder is refused before anything is read.
  std::string read_model_file() const {
    try {
      return platform::read_regular_file(path_, limits_.max_file_bytes);
    } catch (const platform::FileError& e) {
      switch (e.problem()) {
        case platform::FileProblem::NotFound: fail("file not found");
        case platform::FileProblem::TooLarge:
          fail("the file " + std::string(e.what()) + " (LoadLimits::max_file_bytes)");
        default: fail(std::string(e.what()));
      }
    }
  }

  // What tinygltf would build from the JSON, measured before it builds it: depth (its parser of extras
  // and extensions recurses), values, array sizes, the schema's types, the buffers' total size. Then
  // tinygltf parses a document that is known to be within the limits.
  void check_json(std::string_view text, FolderSandbox& box) {
    if (text.size() > limits_.max_json_bytes)
      fail("its JSON is " + str(text.size()) + " bytes, above the limit of " + str(limits_.max_json_bytes) +
           " bytes (LoadLimits::max_json_bytes; put large buffers in a .bin file or a .glb)");
    // One parse, stopped at the first value past the depth or value limit (tinygltf's parser of extras
    // recurses: 20,000 nested arrays overflowed its stack).
    nlohmann::json doc;
    try {
      doc = parse_json_bounded(text, {limits_.max_json_depth, static_cast<std::size_t>(limits_.max_json_values)});
    } catch (const JsonShapeError& e) {
      const std::string what = e.what();
      const char* limit = what.find("deeper") != std::string::npos ? " (LoadLimits::max_json_depth)"
                          : what.find("more than") != std::string::npos ? " (LoadLimits::max_json_values)"
                                                                        : "";
      fail("glTF parser error: " + what + limit);
    }
    // The top-level arrays, before tinygltf turns each element into a structure of up to ~2 KB.
    if (doc.is_object()) {
      for (const auto& [name, value] : doc.items()) {
        if (!value.is_array()) continue;
        const bool nodes = name == "nodes", materials = name == "materials";
        const std::uint64_t limit = nodes ? limits_.max_nodes : materials ? limits_.max_materials : limits_.max_objects;
        if (value.size() > limit)
          fail("the file has " + str(value.size()) + " " + printable(name, 40) + ", above the limit of " + str(limit) +
               " (LoadLimits::" + (nodes ? "max_nodes" : materials ? "max_materials" : "max_objects") + ")");
      }
    }
    try {
      warnings_ = check_gltf_schema(doc);
    } catch (const GltfSchemaError& e) {
      fail(e.what());
    }
    // Every buffer's declared size counts against the scene's budget, before any byte is read or decoded.
    std::uint64_t total = 0;
    if (const auto buffers = doc.find("buffers"); buffers != doc.end()) {
      for (std::size_t i = 0; i < buffers->size(); ++i) {
        const auto& b = (*buffers)[i];
        // An integer >= 1 (the schema check): as a count, saturated where it does not fit 64 bits.
        const double declared = b.contains("byteLength") ? b["byteLength"].get<double>() : 0.0;
        const std::uint64_t length = declared >= 1.8e19 ? kMaxU64 : static_cast<std::uint64_t>(declared);
        total = saturating_add(total, length);
        if (total > limits_.max_buffer_bytes)
          fail("its buffers declare " + (i + 1 < buffers->size() ? "at least " : std::string()) + str(total) +
               " bytes, above the limit of " + str(limits_.max_buffer_bytes) + " bytes for a scene (LoadLimits::max_buffer_bytes)");
        if (!b.contains("uri")) continue;
        const std::string& raw = b["uri"].get_ref<const std::string&>();
        if (raw.starts_with("data:")) {
          check_data_uri(raw, length, i);
        } else {
          const std::string uri = url_decode(raw);
          box.buffer_uris[uri] = std::max(box.buffer_uris[uri], length);
        }
      }
    }
  }

  // A base64 data: URI's decoded size follows from its length: one that disagrees with the buffer's
  // byteLength is refused before tinygltf decodes it (60 MB of it took seconds, to fail anyway).
  void check_data_uri(const std::string& uri, std::uint64_t byte_length, std::size_t buffer) const {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos) return;  // tinygltf refuses it
    const std::size_t chars = uri.size() - comma - 1;
    std::size_t padding = 0;
    for (std::size_t k = uri.size(); k > comma + 1 && uri[k - 1] == '=' && padding < 2; --k) ++padding;
    const std::uint64_t decoded = chars / 4 * 3 + (chars % 4 == 0 ? 0 : chars % 4 - 1) - (chars % 4 == 0 ? padding : 0);
    if (decoded != byte_length)
      fail("buffers[" + str(buffer) + "] has a data: URI holding " + str(decoded) + " bytes, but its byteLength is " +
           str(byte_length) + " (URI " + quote(uri, 60) + ")");
  }

  void parse() {
    const std::string bytes = read_model_file();
    if (bytes.empty()) fail("the file is empty");
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail("files of 4 GiB or more are not supported");

    std::string extension = path_.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const bool magic = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const bool glb = magic || extension == ".glb";
    if (magic && bytes.size() >= 8) {
      // tinygltf ignores the GLB version; glTF 1.0 binaries (version 1) are laid out differently.
      std::uint32_t version = 0;
      std::memcpy(&version, bytes.data() + 4, 4);
      if (version != 2) fail("GLB container version " + str(version) + " is not supported (glTF 2.0 uses version 2)");
    }
    std::string_view json = glb ? std::string_view() : std::string_view(bytes);
    if (magic && bytes.size() >= 12) json = check_glb_chunks(bytes);

    std::error_code ec;
    const fs::path folder = fs::absolute(path_, ec).parent_path();
    if (ec) fail("cannot resolve the file's folder (" + ec.message() + ")");
    std::optional<FolderSandbox> box;
    try {
      box.emplace(folder);
    } catch (const platform::FileError& e) {
      fail("cannot open the file's folder: " + std::string(e.what()));
    }
    // A GLB whose container is broken has no JSON to look at: tinygltf reports what is wrong with it.
    if (!glb || !json.empty()) check_json(json, *box);

    tinygltf::TinyGLTF gltf;
    // WriteWholeFile stays null: loading never writes.
    gltf.SetFsCallbacks({&sandbox_file_exists, &sandbox_expand_path, &sandbox_read_file, nullptr, &*box});
    gltf.SetImageLoader(&decode_image, &image_problems_);
    std::string err, warn;
    bool ok = false;
    try {
      const auto length = static_cast<unsigned int>(bytes.size());
      const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
      ok = glb ? gltf.LoadBinaryFromMemory(&model_, &err, &warn, data, length, box->base_dir)
               : gltf.LoadASCIIFromString(&model_, &err, &warn, bytes.data(), length, box->base_dir);
    } catch (const std::exception& e) {
      fail("glTF parser error: " + printable(e.what()));
    }
    if (!box->problem.empty()) fail(box->problem);
    // tinygltf sometimes records an error and carries on (e.g. a buffer without a URI): still an error.
    // Its messages quote URIs and names from the file: escaped and cut like everything else.
    if (!ok || !err.empty()) {
      std::string message = "glTF parser error: " + (err.empty() ? std::string("(no message)") : printable(err, 400));
      if (!warn.empty()) message += " (warnings: " + printable(warn, 200) + ")";
      fail(message);
    }
  }

  void check_asset() const {
    if (!model_.asset.version.starts_with("2.")) fail("asset version " + quote(model_.asset.version, 40) + " is not glTF 2.x");
    // Extensions that change how geometry is stored; any other required extension (materials,
    // texture transforms, lights...) does not change the triangles we draw.
    for (const std::string& ext : model_.extensionsRequired) {
      if (ext == "KHR_draco_mesh_compression" || ext == "KHR_mesh_quantization" || ext == "EXT_meshopt_compression")
        fail("required extension " + quote(ext, 80) + " is not supported");
    }
  }

  // ---- 2. References, buffer views, accessor layouts.

  struct Kind {
    const char* one;
    const char* many;
  };

  // `index` names an element of an array of `count` `kind`s; -1 means "none" where that is allowed.
  void check_index(int index, std::size_t count, Kind kind, bool optional, const std::string& referrer) const {
    if (optional && index == -1) return;
    if (index < 0 || static_cast<std::size_t>(index) >= count)
      fail(referrer + " refers to " + kind.one + " " + std::to_string(index) + ", which does not exist (the file has " +
           str(count) + " " + (count == 1 ? kind.one : kind.many) + ")");
  }

  // Every index reference tinygltf keeps, whether or not we use the object: a dangling reference means
  // a broken file.
  void check_references() const {
    const auto& m = model_;
    const Kind accessor{"accessor", "accessors"}, buffer_view{"bufferView", "bufferViews"}, buffer{"buffer", "buffers"},
        image{"image", "images"}, sampler{"sampler", "samplers"}, texture{"texture", "textures"},
        material{"material", "materials"}, mesh{"mesh", "meshes"}, node{"node", "nodes"}, camera{"camera", "cameras"},
        skin{"skin", "skins"}, scene{"scene", "scenes"};
    const auto n = [](const auto& v) { return v.size(); };

    for (std::size_t i = 0; i < m.bufferViews.size(); ++i)
      check_index(m.bufferViews[i].buffer, n(m.buffers), buffer, false, "bufferView " + str(i));
    for (std::size_t i = 0; i < m.accessors.size(); ++i) {
      const auto& a = m.accessors[i];
      const std::string who = "accessor " + str(i);
      check_index(a.bufferView, n(m.bufferViews), buffer_view, true, who);
      if (a.sparse.isSparse) {
        check_index(a.sparse.indices.bufferView, n(m.bufferViews), buffer_view, false, who + " (sparse indices)");
        check_index(a.sparse.values.bufferView, n(m.bufferViews), buffer_view, false, who + " (sparse values)");
      }
    }
    for (std::size_t i = 0; i < m.images.size(); ++i)
      check_index(m.images[i].bufferView, n(m.bufferViews), buffer_view, true, "image " + str(i));
    for (std::size_t i = 0; i < m.textures.size(); ++i) {
      check_index(m.textures[i].source, n(m.images), image, true, "texture " + str(i));
      check_index(m.textures[i].sampler, n(m.samplers), sampler, true, "texture " + str(i));
    }
    for (std::size_t i = 0; i < m.materials.size(); ++i) {
      const auto& mat = m.materials[i];
      const std::string who = "material " + str(i);
      for (int t :
           {mat.pbrMetallicRoughness.baseColorTexture.index, mat.pbrMetallicRoughness.metallicRoughnessTexture.index,
            mat.normalTexture.index, mat.occlusionTexture.index, mat.emissiveTexture.index})
        check_index(t, n(m.textures), texture, true, who);
    }
    for (std::size_t i = 0; i < m.meshes.size(); ++i) {
      for (std::size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
        const auto& prim = m.meshes[i].primitives[p];
        const std::string who = "mesh " + str(i) + " primitive " + str(p);
        for (const auto& [name, a] : prim.attributes) check_index(a, n(m.accessors), accessor, false, who + " " + name);
        check_index(prim.indices, n(m.accessors), accessor, true, who + " indices");
        check_index(prim.material, n(m.materials), material, true, who);
        for (const auto& target : prim.targets)
          for (const auto& [name, a] : target)
            check_index(a, n(m.accessors), accessor, false, who + " morph target " + name);
      }
    }
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      const auto& nd = m.nodes[i];
      const std::string who = "node " + str(i);
      check_index(nd.mesh, n(m.meshes), mesh, true, who);
      check_index(nd.camera, n(m.cameras), camera, true, who);
      check_index(nd.skin, n(m.skins), skin, true, who);
      for (int c : nd.children) check_index(c, n(m.nodes), node, false, who + " (children)");
    }
    for (std::size_t i = 0; i < m.skins.size(); ++i) {
      const std::string who = "skin " + str(i);
      check_index(m.skins[i].inverseBindMatrices, n(m.accessors), accessor, true, who);
      check_index(m.skins[i].skeleton, n(m.nodes), node, true, who);
      for (int j : m.skins[i].joints) check_index(j, n(m.nodes), node, false, who + " (joints)");
    }
    for (std::size_t i = 0; i < m.animations.size(); ++i) {
      const auto& anim = m.animations[i];
      const std::string who = "animation " + str(i);
      for (const auto& ch : anim.channels) {
        check_index(ch.sampler, n(anim.samplers), Kind{"animation sampler", "animation samplers"}, false, who);
        check_index(ch.target_node, n(m.nodes), node, true, who);
      }
      for (const auto& s : anim.samplers) {
        check_index(s.input, n(m.accessors), accessor, false, who + " sampler input");
        check_index(s.output, n(m.accessors), accessor, false, who + " sampler output");
      }
    }
    for (std::size_t i = 0; i < m.scenes.size(); ++i)
      for (int nd : m.scenes[i].nodes) check_index(nd, n(m.nodes), node, false, "scene " + str(i));
    check_index(m.defaultScene, n(m.scenes), scene, true, "the default scene");
  }

  // Remembers what each accessor is used for, so that messages can say "accessor 3 (POSITION of mesh 0
  // primitive 0)". Runs after check_references: every index is valid.
  void name_accessor_roles() {
    roles_.assign(model_.accessors.size(), {});
    const auto note = [&](int a, const std::string& role) {
      if (roles_[static_cast<std::size_t>(a)].empty()) roles_[static_cast<std::size_t>(a)] = role;
    };
    for (std::size_t i = 0; i < model_.meshes.size(); ++i) {
      for (std::size_t p = 0; p < model_.meshes[i].primitives.size(); ++p) {
        const auto& prim = model_.meshes[i].primitives[p];
        const std::string where = " of mesh " + str(i) + " primitive " + str(p);
        for (const auto& [name, a] : prim.attributes) note(a, name + where);
        if (prim.indices >= 0) note(prim.indices, "indices" + where);
      }
    }
  }

  std::string accessor_name(int a) const {
    const std::string& role = roles_[static_cast<std::size_t>(a)];
    return "accessor " + std::to_string(a) + (role.empty() ? "" : " (" + role + ")");
  }

  void check_buffer_views() const {
    for (std::size_t i = 0; i < model_.bufferViews.size(); ++i) {
      const auto& view = model_.bufferViews[i];
      const std::string who = "bufferView " + str(i);
      const std::size_t buffer_size = model_.buffers[static_cast<std::size_t>(view.buffer)].data.size();
      if (view.byteLength == 0) fail(who + " has byteLength 0");
      const auto end = mul_add(1, view.byteOffset, view.byteLength);
      if (!end || *end > buffer_size)
        fail(who + " covers bytes " + str(view.byteOffset) + ".." + (end ? str(*end) : "(overflow)") +
             ", past the end of buffer " + std::to_string(view.buffer) + " (" + str(buffer_size) + " bytes)");
      if (view.byteStride > view.byteLength)
        fail(who + " has byteStride " + str(view.byteStride) + ", more than its byteLength " + str(view.byteLength));
    }
  }

  // Component types, counts and strides: what can be checked without looking at byte ranges.
  void check_accessor_layouts() const {
    for (std::size_t i = 0; i < model_.accessors.size(); ++i) {
      const auto& a = model_.accessors[i];
      const int index = static_cast<int>(i);
      if (component_size(a.componentType) == 0)
        fail(accessor_name(index) + " has componentType " + std::to_string(a.componentType) +
             ", which glTF 2.0 does not allow");
      if (a.count == 0) fail(accessor_name(index) + " has count 0");
      if (a.bufferView < 0) continue;
      const auto& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
      if (view.byteStride != 0 && view.byteStride < element_size(a))
        fail(accessor_name(index) + " has " + str(element_size(a)) + "-byte elements, but bufferView " +
             std::to_string(a.bufferView) + " has byteStride " + str(view.byteStride));
    }
  }

  // ---- 3. Node hierarchy.

  // The node's own transform, from its matrix or its translation, rotation and scale.
  glm::dmat4 local_transform(std::size_t i) const {
    const auto& nd = model_.nodes[i];
    const std::string who = node_name(static_cast<int>(i));
    if (!all_finite(nd.matrix) || !all_finite(nd.translation) || !all_finite(nd.rotation) || !all_finite(nd.scale))
      fail(who + " has a transform with a number that is not finite");
    if (!nd.matrix.empty()) {
      if (nd.matrix.size() != 16) fail(who + " matrix has " + str(nd.matrix.size()) + " numbers instead of 16");
      return glm::make_mat4(nd.matrix.data());  // column-major, like glTF
    }
    if (!nd.translation.empty() && nd.translation.size() != 3)
      fail(who + " translation has " + str(nd.translation.size()) + " numbers instead of 3");
    if (!nd.rotation.empty() && nd.rotation.size() != 4)
      fail(who + " rotation has " + str(nd.rotation.size()) + " numbers instead of 4");
    if (!nd.scale.empty() && nd.scale.size() != 3)
      fail(who + " scale has " + str(nd.scale.size()) + " numbers instead of 3");

    glm::dmat4 m(1.0);
    if (!nd.translation.empty()) m = glm::translate(glm::make_vec3(nd.translation.data()));
    if (!nd.rotation.empty()) {
      const auto& r = nd.rotation;  // glTF stores x, y, z, w; glm's constructor takes w first
      const glm::dquat q(r[3], r[0], r[1], r[2]);
      const double length = glm::length(q);
      if (!(length > 0.0)) fail(who + " rotation is a zero quaternion");
      m *= glm::mat4_cast(q / length);  // exporters round; renormalise rather than skew
    }
    if (!nd.scale.empty()) m *= glm::scale(glm::make_vec3(nd.scale.data()));
    return m;
  }

  // glTF nodes form trees: each node has at most one parent and no node is its own ancestor. Checked
  // for all nodes, used or not, together with the depth limit and the transforms.
  void check_nodes() {
    const std::size_t count = model_.nodes.size();
    parent_.assign(count, -1);
    for (std::size_t p = 0; p < count; ++p) {
      for (int c : model_.nodes[p].children) {
        const auto child = static_cast<std::size_t>(c);
        if (parent_[child] == static_cast<int>(p))
          fail("node " + str(p) + " lists node " + str(child) + " twice as a child");
        if (parent_[child] != -1)
          fail("node " + str(child) + " is a child of both node " + std::to_string(parent_[child]) + " and node " +
               str(p) + " (a node may have only one parent)");
        parent_[child] = static_cast<int>(p);
      }
    }

    local_.resize(count);
    for (std::size_t i = 0; i < count; ++i) local_[i] = local_transform(i);

    // Walk down from the parentless nodes. With one parent per node this visits each node at most once;
    // the nodes it never reaches are on a loop or hang below one.
    std::vector<int> depth(count, 0);
    std::vector<std::size_t> stack;
    for (std::size_t i = 0; i < count; ++i) {
      if (parent_[i] == -1) {
        depth[i] = 1;
        stack.push_back(i);
      }
    }
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      if (depth[i] > limits_.max_node_depth)
        fail("node " + str(i) + " is " + std::to_string(depth[i]) + " levels deep, above the limit of " +
             std::to_string(limits_.max_node_depth) + " (LoadLimits::max_node_depth)");
      for (int c : model_.nodes[i].children) {
        depth[static_cast<std::size_t>(c)] = depth[i] + 1;
        stack.push_back(static_cast<std::size_t>(c));
      }
    }
    const auto unreached = std::find(depth.begin(), depth.end(), 0);
    if (unreached == depth.end()) return;
    // Climbing `count` parents from an unreached node surely lands on the loop; then go round it once.
    auto on_loop = static_cast<std::size_t>(unreached - depth.begin());
    for (std::size_t step = 0; step < count; ++step) on_loop = static_cast<std::size_t>(parent_[on_loop]);
    std::vector<std::size_t> ancestors{on_loop};  // on_loop, its parent, its grandparent... round the loop
    for (auto i = static_cast<std::size_t>(parent_[on_loop]); i != on_loop; i = static_cast<std::size_t>(parent_[i]))
      ancestors.push_back(i);
    // Printed from parent to child, at most 8 steps: a crafted loop may hold millions of nodes.
    std::string loop = str(on_loop);
    const std::size_t shown = std::min<std::size_t>(ancestors.size() - 1, 8);
    for (std::size_t k = 0; k < shown; ++k) loop += " -> " + str(ancestors[ancestors.size() - 1 - k]);
    loop += shown + 1 < ancestors.size() ? " -> ... (" + str(ancestors.size()) + " nodes)" : " -> " + str(on_loop);
    fail("nodes form a loop: " + loop + " (each node is a child of the one before)");
  }

  // ---- 4. The scene walk.

  // "node 3" or "node 3 ('wheel')", for messages.
  std::string node_name(int n) const {
    const std::string& name = model_.nodes[static_cast<std::size_t>(n)].name;
    return "node " + std::to_string(n) + (name.empty() ? "" : " (" + quote(name, 60) + ")");
  }

  // The root nodes to draw: the default scene's, scene 0's when none is set, or every parentless node
  // when the file has no scenes.
  std::vector<int> scene_roots() const {
    std::vector<int> roots;
    if (model_.scenes.empty()) {
      for (std::size_t i = 0; i < parent_.size(); ++i)
        if (parent_[i] == -1) roots.push_back(static_cast<int>(i));
      return roots;
    }
    const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    roots = model_.scenes[static_cast<std::size_t>(s)].nodes;
    std::vector<bool> listed(model_.nodes.size(), false);
    for (int r : roots) {
      const auto i = static_cast<std::size_t>(r);
      if (listed[i]) fail("scene " + std::to_string(s) + " lists node " + str(i) + " twice");
      if (parent_[i] != -1)
        fail("scene " + std::to_string(s) + " lists node " + str(i) + ", a child of node " +
             std::to_string(parent_[i]) + " (scene nodes must be roots)");
      listed[i] = true;
    }
    return roots;
  }

  // A POSITION or NORMAL accessor must hold plain floats.
  void check_vec3_float(int index) const {
    const auto& a = model_.accessors[static_cast<std::size_t>(index)];
    check_readable(index);
    if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      fail(accessor_name(index) + " is " + type_name(a.type) + " " + component_name(a.componentType) +
           (a.normalized ? " normalized" : "") + "; it must be VEC3 FLOAT (quantized data is not supported)");
  }

  // Data we read must come from a buffer view: sparse accessors and all-zero accessors (no bufferView)
  // are legal glTF but never useful geometry, so they are not supported.
  void check_readable(int index) const {
    const auto& a = model_.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) fail(accessor_name(index) + " is sparse; sparse accessors are not supported");
    if (a.bufferView < 0) fail(accessor_name(index) + " has no bufferView (all zeros); that is not supported");
  }

  // Checks a triangle primitive's formats and returns how many vertices and triangles it makes.
  std::pair<std::uint64_t, std::uint64_t> check_primitive(std::size_t m, std::size_t p) const {
    const auto& prim = model_.meshes[m].primitives[p];
    const std::string where = "mesh " + str(m) + " primitive " + str(p);
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) fail(where + " has no POSITION attribute");
    check_vec3_float(position->second);
    const std::uint64_t vertices = model_.accessors[static_cast<std::size_t>(position->second)].count;
    // Indices are 32-bit: a primitive may address at most 2^32 vertices.
    if (vertices > std::uint64_t{1} << 32) fail(where + " has " + str(vertices) + " vertices, more than 2^32");
    for (const auto& [name, a] : prim.attributes) {
      const std::uint64_t n = model_.accessors[static_cast<std::size_t>(a)].count;
      if (n != vertices)
        fail(accessor_name(a) + " has count " + str(n) + " but POSITION has " + str(vertices) +
             "; all attributes of a primitive must have the same count");
    }
    if (const auto normal = prim.attributes.find("NORMAL"); normal != prim.attributes.end())
      check_vec3_float(normal->second);

    std::uint64_t corners = vertices;
    if (prim.indices >= 0) {
      const auto& a = model_.accessors[static_cast<std::size_t>(prim.indices)];
      check_readable(prim.indices);
      if (a.type != TINYGLTF_TYPE_SCALAR || (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                             a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                             a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(accessor_name(prim.indices) + " is " + type_name(a.type) + " " + component_name(a.componentType) +
             "; indices must be SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
      corners = a.count;
    }
    const std::string what = prim.indices >= 0 ? " indices" : " vertices";
    if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP || prim.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      if (corners < 3) fail(where + " is a triangle strip or fan with only " + str(corners) + what);
      return {vertices, corners - 2};
    }
    if (corners % 3 != 0) fail(where + " has " + str(corners) + what + ", not a multiple of 3");
    return {vertices, corners / 3};
  }

  // Lists the triangle primitives of the chosen scene with their world transforms. Totals are checked
  // against the limits as the walk goes, from the declared counts, before any geometry is allocated.
  std::vector<Draw> walk_scene() const {
    std::vector<Draw> draws;
    std::uint64_t total_vertices = 0, total_triangles = 0;
    // Node hierarchy checked: a tree walk, finite, each node once.
    std::vector<std::pair<int, glm::dmat4>> stack;
    for (int r : scene_roots()) stack.emplace_back(r, local_[static_cast<std::size_t>(r)]);
    while (!stack.empty()) {
      const auto [n, world] = stack.back();
      stack.pop_back();
      const auto& nd = model_.nodes[static_cast<std::size_t>(n)];
      // Composed transforms may overflow although each node's is finite (scales of 1e200 twice), and
      // vertices are transformed in single precision: every entry must be finite as a float.
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          if (!(std::abs(world[c][r]) <= std::numeric_limits<float>::max()))
            fail(node_name(n) + "'s world transform overflows (an entry is " + std::to_string(world[c][r]) +
                 "; single precision ends at 3.4e38)");
      for (int c : nd.children) stack.emplace_back(c, world * local_[static_cast<std::size_t>(c)]);
      if (nd.mesh < 0) continue;
      const auto m = static_cast<std::size_t>(nd.mesh);
      if (model_.meshes[m].primitives.empty()) fail("mesh " + str(m) + " has no primitives");
      for (std::size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
        const int mode = model_.meshes[m].primitives[p].mode;
        // Points and lines cast no shadows: skipped. Strips and fans are turned into triangle lists.
        if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) continue;
        if (mode != -1 && mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
          fail("mesh " + str(m) + " primitive " + str(p) + " has mode " + std::to_string(mode) +
               ", which is not a glTF primitive mode");
        const auto [vertices, triangles] = check_primitive(m, p);
        total_vertices = saturating_add(total_vertices, vertices);
        total_triangles = saturating_add(total_triangles, triangles);
        if (total_vertices > limits_.max_total_vertices)
          fail("the scene has at least " + str(total_vertices) + " vertices, above the limit of " +
               str(limits_.max_total_vertices) + " (LoadLimits::max_total_vertices; every node instance of a mesh counts)");
        if (total_triangles > limits_.max_total_triangles)
          fail("the scene has at least " + str(total_triangles) + " triangles, above the limit of " +
               str(limits_.max_total_triangles) + " (LoadLimits::max_total_triangles; every node instance of a mesh counts)");
        if (draws.size() >= limits_.max_instances)
          fail("the scene draws more than " + str(limits_.max_instances) +
               " mesh primitives (one per node instance; LoadLimits::max_instances)");
        draws.push_back({n, nd.mesh, static_cast<int>(p), world});
      }
    }
    return draws;
  }

  // ---- 5. Accessor byte ranges.

  void check_accessor_ranges() const {
    for (std::size_t i = 0; i < model_.accessors.size(); ++i) {
      const auto& a = model_.accessors[i];
      if (a.bufferView < 0) continue;  // nothing stored: zeros (or sparse data, never read)
      const auto& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
      const std::uint64_t size = element_size(a);
      const std::uint64_t stride = view.byteStride != 0 ? view.byteStride : size;
      // The last element starts at byteOffset + (count - 1) * stride and is `size` bytes long.
      const auto last = mul_add(a.count - 1, stride, a.byteOffset);
      const auto end = last ? mul_add(1, *last, size) : std::nullopt;
      if (!end || *end > view.byteLength)
        fail(accessor_name(static_cast<int>(i)) + " reads bytes " + str(a.byteOffset) + ".." +
             (end ? str(*end) : "(overflow)") + " past the end of bufferView " + std::to_string(a.bufferView) + " (" +
             str(view.byteLength) + " bytes)");
    }
  }

  // ---- 6. Reading.

  // The bytes of element k of an accessor whose range has been checked.
  const unsigned char* element(const tinygltf::Accessor& a, std::size_t k) const {
    const auto& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_size(a);
    return model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset + a.byteOffset +
           k * stride;
  }

  std::vector<glm::vec3> read_vec3(int index) const {
    const auto& a = model_.accessors[static_cast<std::size_t>(index)];
    std::vector<glm::vec3> out(a.count);
    for (std::size_t k = 0; k < a.count; ++k) {
      float xyz[3];
      std::memcpy(xyz, element(a, k), sizeof(xyz));
      out[k] = glm::vec3(xyz[0], xyz[1], xyz[2]);
    }
    return out;
  }

  // Index values, each checked against the vertex count and the primitive-restart value glTF forbids.
  std::vector<std::uint32_t> read_indices(int index, std::size_t vertices) const {
    const auto& a = model_.accessors[static_cast<std::size_t>(index)];
    const std::size_t size = component_size(a.componentType);
    const std::uint32_t restart = size == 1 ? 0xFFu : size == 2 ? 0xFFFFu : 0xFFFFFFFFu;
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t k = 0; k < a.count; ++k) {
      std::uint32_t v = 0;
      std::memcpy(&v, element(a, k), size);  // little-endian: the low bytes
      if (v == restart)
        fail(accessor_name(index) + " element " + str(k) + " is " + str(v) + ", the primitive-restart value of " +
             component_name(a.componentType) + ", which glTF forbids in indices");
      if (v >= vertices)
        fail(accessor_name(index) + " element " + str(k) + " is " + str(v) + ", but POSITION has only " +
             str(vertices) + " vertices");
      out[k] = v;
    }
    return out;
  }

  // One Texture per glTF texture; the pixels of an image are decoded once and shared by every texture
  // that uses it. A bad or missing image becomes a checker, with one warning naming it and the problem.
  std::vector<Texture> build_textures() {
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
  void apply_material(Mesh& mesh, int material, const tinygltf::Primitive& prim) const {
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

  // A float, normalised unsigned byte or unsigned short attribute (TEXCOORD_n, COLOR_0) as vectors of N
  // floats; COLOR_0 may be VEC3 (alpha 1).
  template <typename V>
  std::vector<V> read_floats(int index, const std::string& what) const {
    const auto& a = model_.accessors[static_cast<std::size_t>(index)];
    const int n = a.type == TINYGLTF_TYPE_VEC2 ? 2 : a.type == TINYGLTF_TYPE_VEC3 ? 3 : a.type == TINYGLTF_TYPE_VEC4 ? 4 : 0;
    const int c = a.componentType;
    if (n == 0 || n > V::length() ||
        !(c == TINYGLTF_COMPONENT_TYPE_FLOAT || ((c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                  c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) && a.normalized)))
      fail(accessor_name(index) + " (" + what + ") must be float or normalised unsigned byte/short vectors");
    const std::size_t size = component_size(c);
    std::vector<V> out(a.count, V(1.0f));
    for (std::size_t k = 0; k < a.count; ++k) {
      const auto* e = element(a, k);
      for (int j = 0; j < n; ++j) {
        float v = 0.0f;
        if (c == TINYGLTF_COMPONENT_TYPE_FLOAT) {
          std::memcpy(&v, e + j * size, sizeof v);
          if (!std::isfinite(v)) fail(accessor_name(index) + " (" + what + ") element " + str(k) + " is not finite");
        } else if (size == 1) {
          v = static_cast<float>(e[j]) / 255.0f;
        } else {
          std::uint16_t u = 0;
          std::memcpy(&u, e + 2 * j, 2);
          v = static_cast<float>(u) / 65535.0f;
        }
        out[k][j] = v;
      }
    }
    return out;
  }

  static std::string where_primitive(const Draw& d) {
    return "mesh " + std::to_string(d.mesh) + " primitive " + std::to_string(d.primitive);
  }

  Mesh build_mesh(const Draw& d) const {
    const auto& gmesh = model_.meshes[static_cast<std::size_t>(d.mesh)];
    const auto& prim = gmesh.primitives[static_cast<std::size_t>(d.primitive)];
    const auto& node = model_.nodes[static_cast<std::size_t>(d.node)];

    Mesh mesh;
    // Names come from the file: kept printable and short, since the panel and render.json show them.
    mesh.name = !gmesh.name.empty() ? printable(gmesh.name, 80)
                : !node.name.empty() ? printable(node.name, 80)
                                     : "mesh " + std::to_string(d.mesh);
    const int position = prim.attributes.at("POSITION");
    mesh.positions = read_vec3(position);
    apply_material(mesh, prim.material, prim);
    if (const auto color = prim.attributes.find("COLOR_0"); color != prim.attributes.end())
      mesh.colors = read_floats<glm::vec4>(color->second, "COLOR_0");
    if ((!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) ||
        (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()))
      fail(where_primitive(d) + ": TEXCOORD or COLOR_0 has a count other than POSITION's");
    for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
      const glm::vec3& p = mesh.positions[k];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(accessor_name(position) + " element " + str(k) + " is not finite");
    }

    std::vector<std::uint32_t> corners;
    if (prim.indices >= 0) {
      corners = read_indices(prim.indices, mesh.positions.size());
    } else {
      corners.resize(mesh.positions.size());
      for (std::size_t k = 0; k < corners.size(); ++k) corners[k] = static_cast<std::uint32_t>(k);
    }
    // Strips and fans as the glTF spec defines them, with the winding of their first triangle.
    if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (std::size_t i = 0; i + 2 < corners.size(); ++i) {
        const std::size_t odd = i % 2;
        mesh.indices.insert(mesh.indices.end(), {corners[i], corners[i + 1 + odd], corners[i + 2 - odd]});
      }
    } else if (prim.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      for (std::size_t i = 0; i + 2 < corners.size(); ++i)
        mesh.indices.insert(mesh.indices.end(), {corners[i + 1], corners[i + 2], corners[0]});
    } else {
      mesh.indices = std::move(corners);
    }

    // Normals from the file when every one is finite and non-zero; otherwise computed from the faces.
    if (const auto normal = prim.attributes.find("NORMAL"); normal != prim.attributes.end()) {
      mesh.normals = read_vec3(normal->second);
      const bool sound = std::all_of(mesh.normals.begin(), mesh.normals.end(), [](const glm::vec3& n) {
        const float length = glm::length(n);
        return std::isfinite(length) && length > 0.0f;
      });
      if (!sound) mesh.normals.clear();
    }
    if (mesh.normals.empty()) compute_normals(mesh);

    return mesh;
  }

  // A model far from the world's origin for its size (a georeferenced site: a few hundred units at a
  // million) would lose its shape in float world coordinates: its vertices are kept relative to the
  // centre of its box instead, found in double. Others keep the world's origin (their file's coordinates).
  static glm::dvec3 far_origin(const std::vector<Mesh>& meshes, const std::vector<Draw>& draws) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < meshes.size(); ++i)
      for (const glm::vec3& p : meshes[i].positions) {
        const glm::dvec3 w(draws[i].world * glm::dvec4(glm::dvec3(p), 1.0));
        if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) continue;  // refused in place_mesh
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
      }
    if (!(lo.x <= hi.x)) return glm::dvec3(0.0);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const double distance = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    // float keeps 2^-24 of the distance: at 16 extents that is 1e-6 of the model's size.
    return distance > kFarOriginExtents * extent ? centre : glm::dvec3(0.0);
  }
  static constexpr double kFarOriginExtents = 16.0;

  // The node's world transform, less the scene's origin (in double), applied to the mesh.
  void place_mesh(Mesh& mesh, const Draw& d, const glm::dvec3& origin) const {
    const std::string where = "mesh " + std::to_string(d.mesh) + " primitive " + std::to_string(d.primitive);
    // Skins and morph targets are ignored: the lab draws the rest pose under the node's transform.
    transform_mesh(mesh, glm::mat4(glm::translate(glm::dmat4(1.0), -origin) * d.world));
    // The camera and light fits square the scene's extent (in float): a scene wider than ~1.8e19 gives
    // NaN matrices and a blank frame. Far below that, max_coordinate keeps the maths and the depth
    // precision meaningful.
    const double limit = limits_.max_coordinate;
    for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
      const glm::vec3& p = mesh.positions[k];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(node_name(d.node) + "'s transform takes " + where + " to non-finite positions");
      const glm::dvec3 world = origin + glm::dvec3(p);
      const double largest = std::max({std::abs(world.x), std::abs(world.y), std::abs(world.z)});
      if (largest > limit) {
        char figures[64];
        std::snprintf(figures, sizeof figures, "%.3g, beyond the limit of %.3g", largest, limit);
        fail(node_name(d.node) + "'s transform takes " + where + " vertex " + str(k) + " to a coordinate of " + figures +
             " (LoadLimits::max_coordinate)");
      }
    }
  }

  fs::path path_;
  LoadLimits limits_;
  mutable std::vector<std::string> warnings_;  // what the specification says to ignore, for the caller
  tinygltf::Model model_;
  ImageProblems image_problems_;
  std::vector<std::string> roles_;  // per accessor: what uses it, for messages
  std::vector<int> parent_;         // per node: its parent, or -1
  std::vector<glm::dmat4> local_;   // per node: its own transform
};

}  // namespace

Scene load_gltf(const std::filesystem::path& path, const LoadLimits& limits, std::vector<std::string>* warnings) {
  Loader loader(path, limits);
  Scene scene = loader.load();
  if (warnings) *warnings = loader.warnings();
  return scene;
}

}  // namespace shadowlab
