// No source reads or writes a parameter by a key nobody declares. Code that reads a parameter through
// its handle (core/params.h, Param<T>) cannot name an undeclared key: it would not compile. What still
// names a key by a string literal (assignments such as "pcf.kernel=3", a lab's presets, ParamSet::set
// with a key, a keyed subset of a family's specs) is checked here: every such literal in the product
// sources must be the key of a declaration, or the test fails and lists file:line of each offender.
//
// A declaration is a spec literal, `{"key", "Label", ParamKind::...`, as every family's table and every
// handle writes it. A use is a string literal shaped `family.name` (optionally `=value`) that either
// starts with a declared family (light., shadow., vsm., ...) or is the argument of a parameter call
// (get*, set*, find, declare, apply_assignment, format, spec_in, *_param*, *_choice), so a typo in the family
// is caught too. Not keys: file names ("scene.gltf") and a check's criteria ("noise.range", followed by
// their Criterion:: comparison).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/cascades.h"
#include "core/flashlight.h"
#include "core/params.h"
#include "core/technique_params.h"
#include "core/vsm_params.h"
#include "renderer/billboards.h"

namespace shadowlab {
namespace {

struct Literal {
  int line = 0;
  std::string text;    // the literal's characters, between the quotes
  std::string before;  // the code before it on its line (comments removed)
  std::string after;   // the code after it on its line and the next one
};

// The string literals of a C++ source with their line and the code around them on their line; comments
// and character literals are skipped. (Raw strings are read as plain ones: none in the tree holds a key.)
std::vector<Literal> string_literals(const std::string& source) {
  // First the code with comments blanked (newlines kept), then the literals on each line.
  std::string code = source;
  enum { Code, Str, Chr, Line, Block } state = Code;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i], next = i + 1 < code.size() ? code[i + 1] : '\0';
    switch (state) {
      case Code:
        if (c == '/' && next == '/') state = Line, code[i] = ' ';
        else if (c == '/' && next == '*') state = Block, code[i] = ' ';
        else if (c == '"') state = Str;
        else if (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(code[i - 1])))) state = Chr;
        break;
      case Str:
      case Chr:
        if (c == '\\') ++i;
        else if ((state == Str && c == '"') || (state == Chr && c == '\'')) state = Code;
        else if (c == '\n') state = Code;
        break;
      case Line:
        if (c == '\n') state = Code;
        else code[i] = ' ';
        break;
      case Block:
        if (c == '*' && next == '/') state = Code, code[i] = code[i + 1] = ' ', ++i;
        else if (c != '\n') code[i] = ' ';
        break;
    }
  }
  std::vector<Literal> out;
  std::vector<std::string> lines;
  std::istringstream in(code);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string& line = lines[n];
    const std::string next = n + 1 < lines.size() ? "\n" + lines[n + 1] : "";
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(line[i - 1])))) {
        for (++i; i < line.size() && line[i] != '\''; ++i)
          if (line[i] == '\\') ++i;
        continue;
      }
      if (line[i] != '"') continue;
      std::size_t end = i + 1;
      for (; end < line.size() && line[end] != '"'; ++end)
        if (line[end] == '\\') ++end;
      out.push_back({static_cast<int>(n) + 1, line.substr(i + 1, end - i - 1), line.substr(0, i),
                     (end < line.size() ? line.substr(end + 1) : "") + next});
      i = end;
    }
  }
  return out;
}

const std::regex kKeyShape(R"(^([a-z][a-z0-9_]*)\.([a-z][a-z0-9_]*)(=.*)?$)");
const std::regex kDeclarationAfter(R"(^\s*,\s*"[^"]*"\s*,\s*ParamKind::)");
// A check's criterion is named like a key ("noise.range") and followed by its Criterion:: comparison.
const std::regex kCriterionAfter(R"(^[^"]*Criterion::)");
// A call that takes a key, just before the literal (as its first argument, after one more, or in a
// braced list of keys).
const std::regex kKeyCall(
    R"(\b(get\w*|set\w*|find|declare|apply_assignment|format|spec_in|\w*_param\w*|\w*_choice)\s*\(\s*(\{\s*|[\w.>\-]+\s*,\s*)?$)");
// Literals shaped like a key that name a file.
const std::regex kFileName(R"(\.(gltf|glb|json|csv|png|txt|md|glsl|vert|frag|geom|comp|h|cpp|py|sh)$)");

struct Offender {
  std::string where;  // file:line
  std::string key;
};

class KeyScan {
 public:
  // Declarations first (from every file), then uses.
  void declare_from(const std::string& source) {
    for (const Literal& l : string_literals(source)) {
      std::smatch m;
      if (std::regex_match(l.text, m, kKeyShape) && !m[3].matched && std::regex_search(l.after, kDeclarationAfter)) {
        keys_.insert(l.text);
        families_.insert(m[1].str());
      }
    }
  }
  void declare_key(const std::string& key) {
    keys_.insert(key);
    families_.insert(key.substr(0, key.find('.')));
  }
  // The undeclared keys `source` names, and counts every key-shaped use.
  std::vector<Offender> check(const std::string& name, const std::string& source) {
    std::vector<Offender> out;
    for (const Literal& l : string_literals(source)) {
      std::smatch m;
      if (!std::regex_match(l.text, m, kKeyShape) || std::regex_search(l.text, kFileName)) continue;
      if (!m[3].matched && std::regex_search(l.after, kDeclarationAfter)) continue;  // a declaration
      if (std::regex_search(l.after, kCriterionAfter)) continue;                     // a criterion's name
      if (!families_.count(m[1].str()) && !std::regex_search(l.before, kKeyCall)) continue;
      ++uses_;
      const std::string key = m[1].str() + "." + m[2].str();
      if (!keys_.count(key)) out.push_back({name + ":" + std::to_string(l.line), key});
    }
    return out;
  }
  const std::set<std::string>& keys() const { return keys_; }
  int uses() const { return uses_; }

 private:
  std::set<std::string> keys_, families_;
  int uses_ = 0;
};

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::filesystem::path> product_sources() {
  namespace fs = std::filesystem;
  std::vector<fs::path> out;
  for (const char* room : {"core", "oracle", "renderer", "grading", "labs", "app"})
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(SHADOWLAB_SOURCE_DIR) / room)) {
      const std::string ext = entry.path().extension().string();
      if (entry.is_regular_file() && (ext == ".cpp" || ext == ".h" || ext == ".hpp")) out.push_back(entry.path());
    }
  std::sort(out.begin(), out.end());
  return out;
}

std::string listed(const std::vector<Offender>& offenders) {
  std::string out;
  for (const auto& o : offenders) out += "  " + o.where + ": \"" + o.key + "\" is declared nowhere\n";
  return out;
}

TEST(ParamKeys, EverySourceNamesOnlyDeclaredKeys) {
  const auto sources = product_sources();
  KeyScan scan;
  for (const auto& path : sources) scan.declare_from(read_text(path));
  // The declaration detector finds every spec the families' tables hold (what the renderer declares).
  std::vector<ParamSpec> tables = renderer_param_specs();
  for (auto group : {vsm_param_specs(), light_param_specs(), pcf_param_specs(), point_param_specs(), volume_param_specs(),
                     csm_param_specs(), flashlight_param_specs(), billboard_param_specs()})
    tables.insert(tables.end(), group.begin(), group.end());
  for (const auto& spec : tables) EXPECT_TRUE(scan.keys().count(spec.key)) << spec.key << " not found as a declaration";

  std::vector<Offender> offenders;
  for (const auto& path : sources) {
    const auto found = scan.check(std::filesystem::relative(path, SHADOWLAB_SOURCE_DIR).generic_string(), read_text(path));
    offenders.insert(offenders.end(), found.begin(), found.end());
  }
  EXPECT_TRUE(offenders.empty()) << "keys no spec declares:\n" << listed(offenders);
  EXPECT_GT(scan.uses(), 200) << "the scan saw too few keys to have read the tree";  // 298 when written
}

// The scan fails on a typo'd key, in the name or in the family, read or written, and passes the right
// ones written differently (a handle, a key among other literals, a file name, a comment).
TEST(ParamKeys, ScanFindsTyposInASnippet) {
  KeyScan scan;
  scan.declare_from(R"(const FloatParam shadow_bias{{"shadow.bias", "Constant bias", ParamKind::Float, 0.005,)");
  scan.declare_key("pcf.kernel");
  const std::string snippet = R"(
    const float a = params.get_float("shadow.bias");     // declared
    const float b = params.get_float("shadow.bais");     // line 3: typo in the name
    const double c = technique_param(params, "shdow.bias");  // line 4: typo in the family (a call)
    p.apply_assignment("pcf.kernl=3");                   // line 5: typo in an assignment
    const auto d = params.get(param::shadow_bias);       // a handle: nothing to check
    sets = {{"pcf.kernel", "3"}, {"shadow.bias=0.01"}};  // declared, in a list and as an assignment
    load("scene.gltf"); write("bench.json");             // file names
    // p.set("shadow.nope", 1) in a comment is no use
    /* nor "shadow.nope2" here */
    char q = '"'; p.set("pcf.kernal", 5);                // line 11: after a quote character
    c.push_back({"shadow.acne", acne, Criterion::kAtMost, 0.01, "a criterion's name, not a key"});
    c.push_back({"shadow.peter_panning", gap,
                 Criterion::kAtMost, 0.02, "on the next line"});
    const BoolParam flag{{"shadow.flag", "A flag",
        ParamKind::Bool, 0.0, 0.0, 1.0, "declared over two lines", {}}};
    params.get_bool("shadow.flag"); params.get_bool("shadow.flga");  // line 17: typo of a two-line declaration
  )";
  scan.declare_from(snippet);
  const auto offenders = scan.check("snippet.cpp", snippet);
  std::vector<std::string> got;
  for (const auto& o : offenders) got.push_back(o.where + " " + o.key);
  EXPECT_EQ(got, (std::vector<std::string>{"snippet.cpp:3 shadow.bais", "snippet.cpp:4 shdow.bias",
                                           "snippet.cpp:5 pcf.kernl", "snippet.cpp:11 pcf.kernal",
                                           "snippet.cpp:17 shadow.flga"}))
      << listed(offenders);
}

}  // namespace
}  // namespace shadowlab
