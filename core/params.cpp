#include "core/params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace shadowlab {

ParamSet::ParamSet(std::vector<ParamSpec> specs) {
  for (auto& s : specs) declare(std::move(s));
}

void ParamSet::declare(ParamSpec spec) {
  const auto it = std::find_if(specs_.begin(), specs_.end(), [&](const ParamSpec& s) { return s.key == spec.key; });
  const double value = spec.default_value;
  if (it == specs_.end()) {
    specs_.push_back(std::move(spec));
    values_.push_back(value);
  } else {
    const auto i = static_cast<std::size_t>(it - specs_.begin());
    specs_[i] = std::move(spec);
    values_[i] = value;
  }
}

const ParamSpec* ParamSet::find(std::string_view key) const {
  for (const auto& s : specs_)
    if (s.key == key) return &s;
  return nullptr;
}

std::size_t ParamSet::index_of(std::string_view key) const {
  for (std::size_t i = 0; i < specs_.size(); ++i)
    if (specs_[i].key == key) return i;
  throw std::out_of_range("unknown parameter '" + std::string(key) + "'");
}

double ParamSet::get(std::string_view key) const { return values_[index_of(key)]; }

double ParamSet::value_or_default(const ParamSpec& spec) const {
  const ParamSpec* own = find(spec.key);
  return own ? values_[static_cast<std::size_t>(own - specs_.data())] : spec.default_value;
}

const std::string& ParamSet::get_choice(std::string_view key) const {
  const std::size_t i = index_of(key);
  return specs_[i].choices.at(static_cast<std::size_t>(values_[i]));
}

namespace {
std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string range_text(const ParamSpec& s) {
  if (s.kind == ParamKind::Bool) return "true or false";
  if (s.kind == ParamKind::Choice) {
    std::string out = "one of";
    for (const auto& c : s.choices) out += " " + c;
    return out;
  }
  return "[" + number_text(s.min) + ", " + number_text(s.max) + "]";
}
}  // namespace

unsigned ParamSet::set(const std::string& key, double value) {
  const std::size_t i = index_of(key);
  const ParamSpec& s = specs_[i];
  bool ok = std::isfinite(value);
  switch (s.kind) {
    case ParamKind::Float: ok = ok && value >= s.min && value <= s.max; break;
    case ParamKind::Int: ok = ok && value == std::floor(value) && value >= s.min && value <= s.max; break;
    case ParamKind::Bool: ok = ok && (value == 0.0 || value == 1.0); break;
    case ParamKind::Choice: ok = ok && value == std::floor(value) && value >= 0 && value < static_cast<double>(s.choices.size()); break;
  }
  if (!ok) throw std::invalid_argument(key + "=" + number_text(value) + " is out of range: expected " + range_text(s));
  if (values_[i] == value) return kInvalidatesNothing;
  values_[i] = value;
  return s.invalidates;
}

unsigned ParamSet::set_from_string(const std::string& key, const std::string& text) {
  const ParamSpec* s = find(key);
  if (!s) throw std::out_of_range("unknown parameter '" + key + "'");
  if (s->kind == ParamKind::Choice) {
    const auto it = std::find(s->choices.begin(), s->choices.end(), text);
    if (it == s->choices.end()) throw std::invalid_argument(key + "=" + text + " is not valid: expected " + range_text(*s));
    return set(key, static_cast<double>(it - s->choices.begin()));
  }
  if (s->kind == ParamKind::Bool) {
    if (text == "true" || text == "on" || text == "1") return set(key, 1.0);
    if (text == "false" || text == "off" || text == "0") return set(key, 0.0);
    throw std::invalid_argument(key + "=" + text + " is not valid: expected " + range_text(*s));
  }
  double value = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size())
    throw std::invalid_argument(key + "=" + text + " is not a number: expected " + range_text(*s));
  return set(key, value);
}

unsigned ParamSet::apply_assignment(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("expected key=value, got '" + assignment + "'");
  const std::string key = assignment.substr(0, eq);
  if (!find(key)) {
    std::string keys;
    for (const auto& s : specs_) keys += (keys.empty() ? "" : ", ") + s.key;
    throw std::invalid_argument("unknown parameter '" + key + "'; valid keys: " + keys);
  }
  return set_from_string(key, assignment.substr(eq + 1));
}

void ParamSet::reset_to_defaults() {
  for (std::size_t i = 0; i < specs_.size(); ++i) values_[i] = specs_[i].default_value;
}

std::string ParamSet::format(const std::string& key) const {
  const std::size_t i = index_of(key);
  const ParamSpec& s = specs_[i];
  switch (s.kind) {
    case ParamKind::Choice: return s.choices.at(static_cast<std::size_t>(values_[i]));
    case ParamKind::Bool: return values_[i] != 0.0 ? "true" : "false";
    default: return number_text(values_[i]);
  }
}

nlohmann::json ParamSet::to_json() const {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const ParamSpec& s = specs_[i];
    switch (s.kind) {
      case ParamKind::Choice: out[s.key] = s.choices.at(static_cast<std::size_t>(values_[i])); break;
      case ParamKind::Bool: out[s.key] = values_[i] != 0.0; break;
      case ParamKind::Int: out[s.key] = static_cast<long long>(values_[i]); break;
      case ParamKind::Float: out[s.key] = values_[i]; break;
    }
  }
  return out;
}

std::vector<std::string> ParamSet::apply_json(const nlohmann::json& values) {
  std::vector<std::string> problems;
  if (!values.is_object()) return {"parameters are not a JSON object"};
  for (const auto& [key, value] : values.items()) {
    try {
      if (!find(key)) throw std::invalid_argument("unknown parameter '" + key + "'");
      if (value.is_string()) set_from_string(key, value.get<std::string>());
      else if (value.is_boolean()) set(key, value.get<bool>() ? 1.0 : 0.0);
      else if (value.is_number()) set(key, value.get<double>());
      else throw std::invalid_argument(key + " has a value of the wrong type");
    } catch (const std::exception& e) {
      problems.emplace_back(e.what());
    }
  }
  return problems;
}

std::vector<std::pair<std::string, double>> ParamSet::values_invalidating(unsigned bits) const {
  std::vector<std::pair<std::string, double>> out;
  values_invalidating(bits, out);
  return out;
}

void ParamSet::values_invalidating(unsigned bits, std::vector<std::pair<std::string, double>>& out) const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    if (!(specs_[i].invalidates & bits)) continue;
    if (n < out.size()) {
      out[n].first = specs_[i].key;  // the same key as last time: its storage is reused
      out[n].second = values_[i];
    } else {
      out.emplace_back(specs_[i].key, values_[i]);
    }
    ++n;
  }
  out.resize(n);
}

const ParamSpec& spec_in(const std::vector<ParamSpec>& all, std::string_view key, const char* family) {
  for (const auto& spec : all)
    if (spec.key == key) return spec;
  throw std::out_of_range(std::string("no ") + family + " parameter " + std::string(key));
}

}  // namespace shadowlab
