// glTF loading, step 1: the file itself, its JSON against the schema, and tinygltf reading it through a
// sandbox that opens files only inside the model's folder (the order of the checks: core/gltf_loader.cpp).
#include "core/gltf_loader_parts.h"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <system_error>

#include <nlohmann/json.hpp>

#include "core/gltf_schema.h"
#include "core/platform.h"

namespace shadowlab::gltf_detail {

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

// Debian's tinygltf trusts a GLB chunk's declared length: a BIN chunk that claims more bytes than the
// file holds makes it copy past the end of the input (found by the fuzzer). Every chunk must fit in
// the file before tinygltf sees it; other container faults (lengths, headers) are left to its parser.
// Returns the JSON chunk (the first chunk, when its type is JSON), for the checks before tinygltf.
std::string_view Loader::check_glb_chunks(std::string_view bytes) {
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
std::string Loader::read_model_file() const {
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
void Loader::check_json(std::string_view text, FolderSandbox& box) {
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
void Loader::check_data_uri(const std::string& uri, std::uint64_t byte_length, std::size_t buffer) const {
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

void Loader::parse() {
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

void Loader::check_asset() const {
  if (!model_.asset.version.starts_with("2.")) fail("asset version " + quote(model_.asset.version, 40) + " is not glTF 2.x");
  // Extensions that change how geometry is stored; any other required extension (materials,
  // texture transforms, lights...) does not change the triangles we draw.
  for (const std::string& ext : model_.extensionsRequired) {
    if (ext == "KHR_draco_mesh_compression" || ext == "KHR_mesh_quantization" || ext == "EXT_meshopt_compression")
      fail("required extension " + quote(ext, 80) + " is not supported");
  }
}
}  // namespace shadowlab::gltf_detail
