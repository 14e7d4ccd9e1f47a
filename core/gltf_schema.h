// The glTF 2.0 core schema's types, checked on the parsed JSON before tinygltf sees it.
//
// tinygltf 2.7 skips a property whose JSON type is wrong (a node name that is a number, primitives
// that are an object, an extension that is a string) as if it were absent, and keeps -1 where an
// index must be >= 0; the Khronos validator reports each as an error, and so does this check. The
// types come from the schema files of the glTF 2.0 specification (glTF.schema.json and the files it
// refers to); see README.md "Robustness" for the decisions.
//
// Errors: a property the schema defines, with the wrong JSON type; an index or count below its
// minimum; an array of the wrong length (matrix 16, rotation 4, translation and scale 3,
// baseColorFactor 4, emissiveFactor 3, min/max 1-16); `extensions` that is not an object of objects.
// Warnings (the specification says clients must ignore what they do not know): a property the core
// schema does not define.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadowlab {

class GltfSchemaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws GltfSchemaError with one printable line naming the property by its JSON path (e.g.
// "nodes[3].name is a number; the glTF 2.0 schema requires a string"). Returns the warnings, at most
// `max_warnings` of them (the last one says how many were left out).
std::vector<std::string> check_gltf_schema(const nlohmann::json& doc, std::size_t max_warnings = 20);

}  // namespace shadowlab
