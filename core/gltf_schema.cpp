#include "core/gltf_schema.h"

#include <cmath>
#include <vector>

#include "core/untrusted.h"

namespace shadowlab {

namespace {

using nlohmann::json;

// The JSON types the core schema uses. Index: a glTFid (integer >= 0). Count: an integer >= 1.
enum class Type {
  String,
  Boolean,
  Number,
  Index,
  Integer,     // any integer (enums of integers: componentType, mode, target, filters)
  UInteger,    // an integer >= 0 (byteOffset, texCoord)
  Count,       // an integer >= 1 (count, byteLength)
  Any,         // extras
  NumberArray,
  IndexArray,
  StringArray,
  Object,       // an object of the kind `spec` names
  ObjectArray,  // an array of such objects
  IndexMap,     // an object whose values are indices (attributes)
  IndexMapArray,  // an array of those (morph targets)
};

struct Spec;

struct Property {
  const char* name;
  Type type;
  const Spec* spec = nullptr;  // Object, ObjectArray
  int min_items = 0;           // arrays: at least this many (0: any)
  int max_items = 0;           // arrays: at most this many (0: any)
};

struct Spec {
  const char* name;  // for messages: the schema's title
  std::vector<Property> properties;
  bool named = true;  // a glTFChildOfRootProperty: has `name`
};

// glTF 2.0 schema, property by property (extensions and extras are common to all, name to the named).
const Spec kTextureInfo{"textureInfo", {{"index", Type::Index}, {"texCoord", Type::UInteger}}, false};
const Spec kNormalTextureInfo{
    "material.normalTextureInfo",
    {{"index", Type::Index}, {"texCoord", Type::UInteger}, {"scale", Type::Number}},
    false};
const Spec kOcclusionTextureInfo{
    "material.occlusionTextureInfo",
    {{"index", Type::Index}, {"texCoord", Type::UInteger}, {"strength", Type::Number}},
    false};
const Spec kPbr{"material.pbrMetallicRoughness",
                {{"baseColorFactor", Type::NumberArray, nullptr, 4, 4},
                 {"baseColorTexture", Type::Object, &kTextureInfo},
                 {"metallicFactor", Type::Number},
                 {"roughnessFactor", Type::Number},
                 {"metallicRoughnessTexture", Type::Object, &kTextureInfo}},
                false};
const Spec kMaterial{"material",
                     {{"pbrMetallicRoughness", Type::Object, &kPbr},
                      {"normalTexture", Type::Object, &kNormalTextureInfo},
                      {"occlusionTexture", Type::Object, &kOcclusionTextureInfo},
                      {"emissiveTexture", Type::Object, &kTextureInfo},
                      {"emissiveFactor", Type::NumberArray, nullptr, 3, 3},
                      {"alphaMode", Type::String},
                      {"alphaCutoff", Type::Number},
                      {"doubleSided", Type::Boolean}}};
const Spec kSparseIndices{"accessor.sparse.indices",
                          {{"bufferView", Type::Index}, {"byteOffset", Type::UInteger}, {"componentType", Type::Integer}},
                          false};
const Spec kSparseValues{"accessor.sparse.values", {{"bufferView", Type::Index}, {"byteOffset", Type::UInteger}}, false};
const Spec kSparse{"accessor.sparse",
                   {{"count", Type::Count},
                    {"indices", Type::Object, &kSparseIndices},
                    {"values", Type::Object, &kSparseValues}},
                   false};
const Spec kAccessor{"accessor",
                     {{"bufferView", Type::Index},
                      {"byteOffset", Type::UInteger},
                      {"componentType", Type::Integer},
                      {"normalized", Type::Boolean},
                      {"count", Type::Count},
                      {"type", Type::String},
                      {"max", Type::NumberArray, nullptr, 1, 16},
                      {"min", Type::NumberArray, nullptr, 1, 16},
                      {"sparse", Type::Object, &kSparse}}};
const Spec kTarget{"animation.channel.target", {{"node", Type::Index}, {"path", Type::String}}, false};
const Spec kChannel{"animation.channel", {{"sampler", Type::Index}, {"target", Type::Object, &kTarget}}, false};
const Spec kAnimationSampler{
    "animation.sampler", {{"input", Type::Index}, {"interpolation", Type::String}, {"output", Type::Index}}, false};
const Spec kAnimation{"animation",
                      {{"channels", Type::ObjectArray, &kChannel, 1},
                       {"samplers", Type::ObjectArray, &kAnimationSampler, 1}}};
const Spec kAsset{"asset",
                  {{"copyright", Type::String},
                   {"generator", Type::String},
                   {"version", Type::String},
                   {"minVersion", Type::String}},
                  false};
const Spec kBuffer{"buffer", {{"uri", Type::String}, {"byteLength", Type::Count}}};
const Spec kBufferView{"bufferView",
                       {{"buffer", Type::Index},
                        {"byteOffset", Type::UInteger},
                        {"byteLength", Type::Count},
                        {"byteStride", Type::Integer},
                        {"target", Type::Integer}}};
const Spec kOrthographic{
    "camera.orthographic",
    {{"xmag", Type::Number}, {"ymag", Type::Number}, {"zfar", Type::Number}, {"znear", Type::Number}},
    false};
const Spec kPerspective{
    "camera.perspective",
    {{"aspectRatio", Type::Number}, {"yfov", Type::Number}, {"zfar", Type::Number}, {"znear", Type::Number}},
    false};
const Spec kCamera{"camera",
                   {{"orthographic", Type::Object, &kOrthographic},
                    {"perspective", Type::Object, &kPerspective},
                    {"type", Type::String}}};
const Spec kImage{"image", {{"uri", Type::String}, {"mimeType", Type::String}, {"bufferView", Type::Index}}};
const Spec kPrimitive{"mesh.primitive",
                      {{"attributes", Type::IndexMap},
                       {"indices", Type::Index},
                       {"material", Type::Index},
                       {"mode", Type::Integer},
                       {"targets", Type::IndexMapArray, nullptr, 1}},
                      false};
const Spec kMesh{"mesh", {{"primitives", Type::ObjectArray, &kPrimitive, 1}, {"weights", Type::NumberArray, nullptr, 1}}};
const Spec kNode{"node",
                 {{"camera", Type::Index},
                  {"children", Type::IndexArray, nullptr, 1},
                  {"skin", Type::Index},
                  {"matrix", Type::NumberArray, nullptr, 16, 16},
                  {"mesh", Type::Index},
                  {"rotation", Type::NumberArray, nullptr, 4, 4},
                  {"scale", Type::NumberArray, nullptr, 3, 3},
                  {"translation", Type::NumberArray, nullptr, 3, 3},
                  {"weights", Type::NumberArray, nullptr, 1}}};
const Spec kSampler{"sampler",
                    {{"magFilter", Type::Integer},
                     {"minFilter", Type::Integer},
                     {"wrapS", Type::Integer},
                     {"wrapT", Type::Integer}}};
const Spec kScene{"scene", {{"nodes", Type::IndexArray, nullptr, 1}}};
const Spec kSkin{"skin",
                 {{"inverseBindMatrices", Type::Index}, {"skeleton", Type::Index}, {"joints", Type::IndexArray, nullptr, 1}}};
const Spec kTexture{"texture", {{"sampler", Type::Index}, {"source", Type::Index}}};
const Spec kRoot{"glTF",
                 {{"extensionsUsed", Type::StringArray, nullptr, 1},
                  {"extensionsRequired", Type::StringArray, nullptr, 1},
                  {"accessors", Type::ObjectArray, &kAccessor, 1},
                  {"animations", Type::ObjectArray, &kAnimation, 1},
                  {"asset", Type::Object, &kAsset},
                  {"buffers", Type::ObjectArray, &kBuffer, 1},
                  {"bufferViews", Type::ObjectArray, &kBufferView, 1},
                  {"cameras", Type::ObjectArray, &kCamera, 1},
                  {"images", Type::ObjectArray, &kImage, 1},
                  {"materials", Type::ObjectArray, &kMaterial, 1},
                  {"meshes", Type::ObjectArray, &kMesh, 1},
                  {"nodes", Type::ObjectArray, &kNode, 1},
                  {"samplers", Type::ObjectArray, &kSampler, 1},
                  {"scene", Type::Index},
                  {"scenes", Type::ObjectArray, &kScene, 1},
                  {"skins", Type::ObjectArray, &kSkin, 1},
                  {"textures", Type::ObjectArray, &kTexture, 1}},
                 false};

const char* json_type(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "binary data";
  }
}

// JSON Schema (2020-12, which the glTF 2.0 schema uses): an integer is a number with no fraction.
bool is_integer(const json& v) {
  if (v.is_number_integer()) return true;
  if (!v.is_number_float()) return false;
  const double d = v.get<double>();
  return std::isfinite(d) && d == std::trunc(d);
}

double number(const json& v) { return v.get<double>(); }

class Checker {
 public:
  explicit Checker(std::size_t max_warnings) : max_warnings_(max_warnings) {}

  void root(const json& doc) {
    if (!doc.is_object()) fail("the document", "is " + std::string(json_type(doc)) + "; a glTF file is a JSON object");
    object(doc, kRoot, "");
  }

  std::vector<std::string> warnings() const {
    std::vector<std::string> out = warnings_;
    if (unreported_ > 0) out.push_back("and " + std::to_string(unreported_) + " more properties the glTF 2.0 schema does not define");
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw GltfSchemaError(path + " " + problem);
  }
  [[noreturn]] void mismatch(const std::string& path, const json& v, const std::string& wanted) const {
    fail(path, "is " + std::string(json_type(v)) + "; the glTF 2.0 schema requires " + wanted);
  }

  static std::string member(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  void object(const json& v, const Spec& spec, const std::string& path) {
    if (!v.is_object()) mismatch(path, v, "an object (" + std::string(spec.name) + ")");
    for (const auto& [key, value] : v.items()) {
      const std::string where = member(path, printable(key, 64));
      if (key == "extensions") {
        extensions(value, where);
        continue;
      }
      if (key == "extras") continue;  // any JSON value: application data
      if (key == "name" && spec.named) {
        if (!value.is_string()) mismatch(where, value, "a string");
        continue;
      }
      const Property* property = nullptr;
      for (const Property& p : spec.properties)
        if (key == p.name) property = &p;
      if (!property) {
        if (warnings_.size() < max_warnings_)
          warnings_.push_back(where + " is not a glTF 2.0 " + spec.name + " property; ignored");
        else
          ++unreported_;
        continue;
      }
      check(value, *property, where);
    }
  }

  // `extensions`: an object whose members are objects (extension.schema.json). Their content is the
  // extension's own schema, which this lab does not know: it is not looked into.
  void extensions(const json& v, const std::string& path) {
    if (!v.is_object()) mismatch(path, v, "an object");
    for (const auto& [name, ext] : v.items())
      if (!ext.is_object()) mismatch(member(path, printable(name, 64)), ext, "an object");
  }

  void index(const json& v, const std::string& path, long long min, const char* wanted) {
    if (!is_integer(v)) mismatch(path, v, wanted);
    if (number(v) < static_cast<double>(min))
      fail(path, "is " + v.dump() + "; the glTF 2.0 schema requires " + wanted);
  }

  void items(const json& v, const Property& p, const std::string& path) {
    if (!v.is_array()) mismatch(path, v, "an array");
    const auto n = static_cast<int>(std::min<std::size_t>(v.size(), 1u << 30));
    const bool fixed = p.min_items > 0 && p.min_items == p.max_items;
    if ((p.min_items > 0 && n < p.min_items) || (p.max_items > 0 && n > p.max_items)) {
      const std::string wanted = fixed ? std::to_string(p.min_items)
                                 : p.max_items > 0 ? std::to_string(p.min_items) + " to " + std::to_string(p.max_items)
                                                   : "at least " + std::to_string(p.min_items);
      fail(path, "has " + std::to_string(v.size()) + " elements; the glTF 2.0 schema requires " + wanted);
    }
  }

  void check(const json& v, const Property& p, const std::string& path) {
    switch (p.type) {
      case Type::String:
        if (!v.is_string()) mismatch(path, v, "a string");
        return;
      case Type::Boolean:
        if (!v.is_boolean()) mismatch(path, v, "a boolean");
        return;
      case Type::Number:
        if (!v.is_number()) mismatch(path, v, "a number");
        return;
      case Type::Index: index(v, path, 0, "an index (an integer >= 0)"); return;
      case Type::Integer:
        if (!is_integer(v)) mismatch(path, v, "an integer");
        return;
      case Type::UInteger: index(v, path, 0, "an integer >= 0"); return;
      case Type::Count: index(v, path, 1, "an integer >= 1"); return;
      case Type::Any: return;
      case Type::NumberArray:
        items(v, p, path);
        for (std::size_t i = 0; i < v.size(); ++i)
          if (!v[i].is_number()) mismatch(path + "[" + std::to_string(i) + "]", v[i], "a number");
        return;
      case Type::IndexArray:
        items(v, p, path);
        for (std::size_t i = 0; i < v.size(); ++i)
          index(v[i], path + "[" + std::to_string(i) + "]", 0, "an index (an integer >= 0)");
        return;
      case Type::StringArray:
        items(v, p, path);
        for (std::size_t i = 0; i < v.size(); ++i)
          if (!v[i].is_string()) mismatch(path + "[" + std::to_string(i) + "]", v[i], "a string");
        return;
      case Type::Object: object(v, *p.spec, path); return;
      case Type::ObjectArray:
        items(v, p, path);
        for (std::size_t i = 0; i < v.size(); ++i) object(v[i], *p.spec, path + "[" + std::to_string(i) + "]");
        return;
      case Type::IndexMap:
        if (!v.is_object()) mismatch(path, v, "an object");
        for (const auto& [key, value] : v.items())
          index(value, member(path, printable(key, 64)), 0, "an index (an integer >= 0)");
        return;
      case Type::IndexMapArray:
        items(v, p, path);
        for (std::size_t i = 0; i < v.size(); ++i) {
          const std::string where = path + "[" + std::to_string(i) + "]";
          check(v[i], Property{p.name, Type::IndexMap}, where);
        }
        return;
    }
  }

  std::size_t max_warnings_;
  std::vector<std::string> warnings_;
  std::size_t unreported_ = 0;
};

}  // namespace

std::vector<std::string> check_gltf_schema(const nlohmann::json& doc, std::size_t max_warnings) {
  Checker checker(max_warnings);
  checker.root(doc);
  return checker.warnings();
}

}  // namespace shadowlab
