#include "app/grade_report.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <ctime>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>


#include "grading/lab.h"
#include "labs/registry.h"
#include "core/image_io.h"

namespace shadowlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr std::uint64_t kMaxRecordBytes = 16ull << 20;  // a lab's record or a check's JSON: a few KB

std::string lab_name(int lab) {
  const Lab* l = find_lab(lab);
  char text[96];
  std::snprintf(text, sizeof text, "lab %d %s", lab, l ? l->slug.c_str() : "?");
  return text;
}

std::string utc_now() {
  // The calendar of <chrono> (C++20), not gmtime_r or gmtime_s: the same code on every system.
  using namespace std::chrono;
  const auto now = floor<seconds>(system_clock::now());
  const auto day = floor<days>(now);
  const year_month_day date(day);
  const hh_mm_ss time(now - day);
  char text[32];
  std::snprintf(text, sizeof text, "%04d-%02u-%02uT%02d:%02d:%02dZ", static_cast<int>(date.year()),
                static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()), static_cast<int>(time.hours().count()),
                static_cast<int>(time.minutes().count()), static_cast<int>(time.seconds().count()));
  return text;
}

// ---- the formats --------------------------------------------------------------------------------

// A CSV field: report_text, a newline shown as \n (one row is one line), quoted when it holds a comma
// or a quote, and a text starting like a formula (= + - @) prefixed with ' so that a spreadsheet shows
// it instead of computing it.
std::string csv_field(const std::string& s) {
  std::string t;
  for (char c : report_text(s)) t += c == '\n' ? std::string("\\n") : std::string(1, c);
  if (!t.empty() && std::strchr("=+-@", t.front())) t.insert(0, "'");
  if (t.find_first_of(",\"") == std::string::npos) return t;
  std::string q = "\"";
  for (char c : t) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string number_text(const json& v) {
  if (!v.is_number()) return "";
  std::ostringstream s;
  s.precision(9);
  s << v.get<double>();
  return s.str();
}

// XML 1.0 text: report_text (no control characters left but tab and newline), and the five entities.
std::string xml_text(const std::string& s) {
  std::string out;
  for (char c : report_text(s)) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// What a student reads about one lab: the status, the message, and each failed criterion's sentence
// (the measured fact, the limit and what to change).
std::string lab_output(const json& record) {
  std::string out = record.value("status", "") + ": " + record.value("message", "");
  for (const auto& c : record.value("criteria", json::array()))
    if (!c.value("passed", false)) out += "\n- " + c.value("sentence", c.value("metric", ""));
  return out;
}

void write_csv(const OutFolder& out, const std::string& file, const json& students) {
  std::string text = "student,lab,slug,status,criterion,value,op,limit,criterion_passed,seconds,peak_memory_mb,message\n";
  for (const auto& s : students) {
    for (const auto& r : s["labs"]) {
      const std::string head = csv_field(s.value("name", "")) + "," + std::to_string(r.value("lab", -1)) + "," +
                               csv_field(r.value("slug", "")) + "," + csv_field(r.value("status", "")) + ",";
      const std::string tail = "," + number_text(r["seconds"]) + "," + number_text(r["peak_memory_mb"]) + "," +
                               csv_field(r.value("message", "")) + "\n";
      const json criteria = r.value("criteria", json::array());
      if (criteria.empty()) text += head + ",,,," + tail;
      for (const auto& c : criteria)
        text += head + csv_field(c.value("metric", "")) + "," + number_text(c["value"]) + "," +
                csv_field(c.value("op", "")) + "," + number_text(c["limit"]) + "," +
                (c.value("passed", false) ? "true" : "false") + tail;
    }
  }
  out.write(file, text);
}

// One lab as a JUnit test case: passed, <skipped> (missing: not handed in), <error> (grader_error) or
// <failure> (type: the status).
std::string junit_case(const std::string& classname, const json& r) {
  const std::string status = r.value("status", "");
  std::string text = "    <testcase classname=\"" + classname + "\" name=\"" + xml_text(lab_name(r.value("lab", -1))) +
                     "\" time=\"" + std::to_string(r.value("seconds", 0.0)) + "\"";
  if (status == "passed") return text + "/>\n";
  const std::string message = r.value("message", "");
  const std::string first_line = xml_text(message.substr(0, message.find('\n')));
  if (status == "missing") return text + ">\n      <skipped message=\"" + first_line + "\"/>\n    </testcase>\n";
  const std::string tag = status == "grader_error" ? "error" : "failure";
  return text + ">\n      <" + tag + " type=\"" + xml_text(status) + "\" message=\"" + first_line + "\">" +
         xml_text(lab_output(r)) + "</" + tag + ">\n    </testcase>\n";
}

void write_junit(const OutFolder& out, const std::string& file, const json& students) {
  std::map<std::string, int> all;  // tests, failures, errors, skipped
  std::string suites;
  for (const auto& s : students) {
    std::map<std::string, int> n;
    double seconds = 0.0;
    std::string cases;
    const std::string name = xml_text(s.value("name", ""));
    for (const auto& r : s["labs"]) {
      const std::string status = r.value("status", "");
      seconds += r.value("seconds", 0.0);
      n["tests"]++;
      if (status != "passed")
        n[status == "grader_error" ? "errors" : status == "missing" ? "skipped" : "failures"]++;
      cases += junit_case(name, r);
    }
    for (const auto& [key, count] : n) all[key] += count;
    suites += "  <testsuite name=\"" + name + "\" tests=\"" + std::to_string(n["tests"]) + "\" failures=\"" +
              std::to_string(n["failures"]) + "\" errors=\"" + std::to_string(n["errors"]) + "\" skipped=\"" +
              std::to_string(n["skipped"]) + "\" time=\"" + std::to_string(seconds) + "\">\n" + cases + "  </testsuite>\n";
  }
  out.write(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"shadowlab grade\" tests=\"" +
                      std::to_string(all["tests"]) + "\" failures=\"" + std::to_string(all["failures"]) +
                      "\" errors=\"" + std::to_string(all["errors"]) + "\" skipped=\"" + std::to_string(all["skipped"]) +
                      "\">\n" + suites + "</testsuites>\n");
}

// Gradescope's autograder results (https://gradescope-autograders.readthedocs.io, "Output format"):
// one test per lab worth 1 point, passed or not (a missing lab is a failed test whose output says
// "missing"), with what to change in its output.
json gradescope_results(const json& student) {
  json tests = json::array();
  double score = 0;
  for (const auto& r : student["labs"]) {
    const int lab = r.value("lab", -1);
    const Lab* l = find_lab(lab);
    const bool passed = r.value("status", "") == "passed";
    score += passed ? 1 : 0;
    tests.push_back({{"name", "Lab " + std::to_string(lab) + ": " + (l ? l->title : std::string("?"))},
                     {"number", std::to_string(lab)},
                     {"score", passed ? 1 : 0},
                     {"max_score", 1},
                     {"status", passed ? "passed" : "failed"},
                     {"output", lab_output(r)},
                     {"visibility", "visible"}});
  }
  return {{"score", score},
          {"output", std::to_string(static_cast<int>(score)) + " of " + std::to_string(tests.size()) +
                         " labs passed (shadowlab grade)"},
          {"visibility", "visible"},
          {"stdout_visibility", "hidden"},
          {"tests", tests}};
}

// ---- report_text -------------------------------------------------------------------------------

// The length of the valid UTF-8 sequence at the start of `s` (RFC 3629: no overlong forms, no
// surrogates, nothing past U+10FFFF), or 0 when its first byte starts none.
std::size_t utf8_sequence(std::string_view s) {
  const auto c = static_cast<unsigned char>(s[0]);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the second byte's range
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c == 0xE0) n = 3, lo = 0xA0;
  else if (c == 0xED) n = 3, hi = 0x9F;
  else if (c >= 0xE1 && c <= 0xEF) n = 3;
  else if (c == 0xF0) n = 4, lo = 0x90;
  else if (c == 0xF4) n = 4, hi = 0x8F;
  else if (c >= 0xF1 && c <= 0xF3) n = 4;
  if (n == 0 || s.size() < n) return 0;
  const auto second = static_cast<unsigned char>(s[1]);
  if (second < lo || second > hi) return 0;
  for (std::size_t i = 2; i < n; ++i)
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) return 0;
  return n;
}

// Puts every string and key of `value` through report_text, in place (a class's results.json is tens of
// MB: no second copy of it).
void make_printable(json& value) {
  if (value.is_string()) {
    std::string& text = value.get_ref<std::string&>();
    if (std::string shown = report_text(text); shown != text) text = std::move(shown);
    return;
  }
  if (value.is_array()) {
    for (auto& v : value) make_printable(v);
    return;
  }
  if (!value.is_object()) return;
  bool keys_printable = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    make_printable(it.value());
    keys_printable = keys_printable && report_text(it.key()) == it.key();
  }
  if (keys_printable) return;
  json out = json::object();
  for (auto it = value.begin(); it != value.end(); ++it) out[report_text(it.key())] = std::move(it.value());
  value = std::move(out);
}

// ---- the merge ---------------------------------------------------------------------------------

json read_json_in(const OutFolder& dir, const std::string& name) {
  const std::optional<std::string> text = dir.read(name, kMaxRecordBytes);
  return text ? json::parse(*text, nullptr, /*allow_exceptions=*/false) : json();
}

// A lab's record as the grader writes it (anything else in a student's folder is not one).
bool is_record(const json& r) {
  return r.is_object() && r.value("schema", json()) == "shadowlab-grade-lab" && r.contains("lab") &&
         r["lab"].is_number_integer() && r.value("status", json()).is_string() && r.value("message", json()).is_string();
}

// One student's records from their folder (none when it is missing, or a link: nothing is read through
// it), with a grader_error "no result" for each lab the grading planned (submission.json, written
// before the first lab ran) and never recorded; for a student with neither, every lab of `labs`.
std::map<int, json> student_records(const std::optional<OutFolder>& dir, const std::string& name, json& submission,
                                    const std::vector<int>& labs) {
  std::set<int> planned;
  std::map<int, json> records;
  if (dir) {
    submission = read_json_in(*dir, "submission.json");
    if (submission.is_object())
      for (const auto& n : submission.value("labs", json::array()))
        if (n.is_number_integer()) planned.insert(n.get<int>());
    for (const auto& file : dir->names()) {
      if (file.rfind("lab_", 0) != 0 || fs::path(file).extension() != ".json" || file.find(".check.") != std::string::npos)
        continue;
      const json r = read_json_in(*dir, file);
      if (is_record(r)) records[r["lab"].get<int>()] = r;
    }
  }
  if (planned.empty() && records.empty()) planned.insert(labs.begin(), labs.end());
  for (int lab : planned)
    if (!records.count(lab))
      records[lab] = lab_record(lab, name, "grader_error",
                                "no result: this lab's grading did not finish (the run was killed, or has not "
                                "reached it); grade again to continue");
  return records;
}

// The class's reports from the students as merged (results.json last: it takes `students` over).
void write_reports(const OutFolder& out, json students, const std::set<int>& all_labs, const MergeSummary& summary,
                   const std::map<std::string, int>& by_status) {
  write_csv(out, "results.csv", students);
  write_junit(out, "junit.xml", students);
  const OutFolder gradescope = out.folder("gradescope");
  for (const auto& s : students) gradescope.folder(s.value("name", "")).write("results.json", report_json(gradescope_results(s)));
  json labs = json::array();
  for (int n : all_labs) {
    const Lab* l = find_lab(n);
    labs.push_back({{"lab", n}, {"slug", l ? l->slug : ""}, {"title", l ? l->title : ""},
                    {"files", l ? l->exercise_files : std::vector<std::string>{}}});
  }
  int all_passed = 0;
  for (const auto& s : students) all_passed += s["score"] == s["max_score"];
  json report = {{"schema", "shadowlab-grade"},
                 {"version", kGradeSchemaVersion},
                 {"generated", utc_now()},
                 {"statuses", kGradeStatuses},
                 {"labs", labs},
                 {"summary",
                  {{"students", summary.students},
                   {"students_all_passed", all_passed},
                   {"labs_graded", summary.labs},
                   {"by_status", by_status}}}};
  report["students"] = std::move(students);
  out.write("results.json", report_json(std::move(report)));
}

}  // namespace

std::string report_text(std::string_view text) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence(text.substr(i));
    const auto c = static_cast<unsigned char>(text[i]);
    const bool control = (n == 1 && ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7f)) ||
                         (n == 2 && c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0);
    const std::size_t take = n == 0 ? 1 : n;
    if (n == 0 || control) {
      for (std::size_t k = i; k < i + take; ++k) {
        const auto b = static_cast<unsigned char>(text[k]);
        out += "\\x";
        out += hex[b >> 4];
        out += hex[b & 15];
      }
    } else {
      out.append(text.substr(i, take));
    }
    i += take;
  }
  return out;
}

std::string report_json(json value) {
  make_printable(value);
  return value.dump(2) + "\n";
}

json lab_record(int lab, const std::string& student, const std::string& status, const std::string& message) {
  const Lab* l = find_lab(lab);
  json files = json::array();
  if (l)
    for (const auto& f : l->exercise_files) files.push_back(f);
  return {{"schema", "shadowlab-grade-lab"}, {"version", kGradeSchemaVersion}, {"student", student},
          {"lab", lab},                      {"slug", l ? l->slug : ""},          {"status", status},
          {"message", message},              {"files", files},                    {"seconds", 0.0},
          {"peak_memory_mb", 0.0},           {"criteria", json::array()},         {"images", json::array()}};
}

MergeSummary merge_grades(const OutFolder& out, const std::vector<std::string>& expected, const std::vector<int>& labs_expected) {
  std::set<std::string> names(expected.begin(), expected.end());
  const std::optional<OutFolder> students_dir = out.existing_folder("students");
  if (students_dir)
    for (const auto& name : students_dir->names(/*folders_only=*/true)) names.insert(name);

  MergeSummary summary;
  std::map<std::string, int> by_status;
  for (const auto& s : kGradeStatuses) by_status[s] = 0;
  std::set<int> all_labs;
  json students = json::array();
  for (const auto& name : names) {
    json submission;
    std::map<int, json> records =
        student_records(students_dir ? students_dir->existing_folder(name) : std::nullopt, name, submission, labs_expected);
    json labs = json::array();
    int passed = 0;
    for (auto& [lab, r] : records) {
      all_labs.insert(lab);
      const std::string status = r.value("status", "grader_error");
      by_status[status]++;
      passed += status == "passed";
      summary.grader_errors += status == "grader_error";
      summary.missing += status == "missing";
      r.erase("schema");
      r.erase("version");
      r.erase("student");
      labs.push_back(std::move(r));
    }
    summary.labs += static_cast<int>(labs.size());
    summary.passed += passed;
    json student = {{"name", name},
                    {"source", submission.is_object() ? submission.value("source", json("")) : json("")},
                    {"score", passed},
                    {"max_score", labs.size()},
                    {"labs", labs}};
    if (submission.is_object() && submission.contains("error")) student["error"] = submission["error"];
    students.push_back(std::move(student));
  }
  summary.students = static_cast<int>(students.size());
  write_reports(out, std::move(students), all_labs, summary, by_status);
  for (const char* file : {"results.json", "results.csv", "junit.xml"}) summary.written.push_back((out.path() / file).string());
  summary.written.push_back((out.path() / "gradescope" / "<student>" / "results.json").string());
  return summary;
}

}  // namespace shadowlab
