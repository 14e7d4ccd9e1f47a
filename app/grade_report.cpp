#include "app/grade_report.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "labs/lab.h"
#include "renderer/image_io.h"

namespace shadowlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_json(const fs::path& path) {
  std::ifstream in(path);
  return json::parse(in, nullptr, /*allow_exceptions=*/false);
}

std::string lab_name(int lab) {
  const Lab* l = find_lab(lab);
  char text[96];
  std::snprintf(text, sizeof text, "lab %d %s", lab, l ? l->slug.c_str() : "?");
  return text;
}

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

// ---- the formats --------------------------------------------------------------------------------

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string number_text(const json& v) {
  if (!v.is_number()) return "";
  std::ostringstream s;
  s.precision(9);
  s << v.get<double>();
  return s.str();
}

// XML 1.0 text: the five entities, and no control characters but tab and newline.
std::string xml_text(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (c < 0x20 && c != '\t' && c != '\n') out += ' ';
        else out += static_cast<char>(c);
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

void write_csv(const fs::path& path, const json& students) {
  std::string text = "student,lab,slug,status,criterion,value,op,limit,criterion_passed,seconds,peak_memory_mb,message\n";
  for (const auto& s : students) {
    for (const auto& r : s["labs"]) {
      const std::string head = csv_field(s.value("name", "")) + "," + std::to_string(r.value("lab", -1)) + "," +
                               csv_field(r.value("slug", "")) + "," + r.value("status", "") + ",";
      const std::string tail = "," + number_text(r["seconds"]) + "," + number_text(r["peak_memory_mb"]) + "," +
                               csv_field(r.value("message", "")) + "\n";
      const json criteria = r.value("criteria", json::array());
      if (criteria.empty()) text += head + ",,,," + tail;
      for (const auto& c : criteria)
        text += head + csv_field(c.value("metric", "")) + "," + number_text(c["value"]) + "," + c.value("op", "") + "," +
                number_text(c["limit"]) + "," + (c.value("passed", false) ? "true" : "false") + tail;
    }
  }
  write_text_atomic(path, text);
}

void write_junit(const fs::path& path, const json& students) {
  int tests = 0, failures = 0, errors = 0;
  std::string suites;
  for (const auto& s : students) {
    int s_failures = 0, s_errors = 0;
    double s_time = 0.0;
    std::string cases;
    const std::string name = xml_text(s.value("name", ""));
    for (const auto& r : s["labs"]) {
      const std::string status = r.value("status", "");
      const double seconds = r.value("seconds", 0.0);
      s_time += seconds;
      cases += "    <testcase classname=\"" + name + "\" name=\"" + xml_text(lab_name(r.value("lab", -1))) + "\" time=\"" +
               std::to_string(seconds) + "\"";
      if (status == "passed") {
        cases += "/>\n";
        continue;
      }
      const bool error = status == "grader_error";
      (error ? s_errors : s_failures)++;
      const std::string tag = error ? "error" : "failure";
      const std::string message = r.value("message", "");
      cases += ">\n      <" + tag + " type=\"" + status + "\" message=\"" + xml_text(message.substr(0, message.find('\n'))) + "\">" +
               xml_text(lab_output(r)) + "</" + tag + ">\n    </testcase>\n";
    }
    const int n = static_cast<int>(s["labs"].size());
    tests += n;
    failures += s_failures;
    errors += s_errors;
    suites += "  <testsuite name=\"" + name + "\" tests=\"" + std::to_string(n) + "\" failures=\"" +
              std::to_string(s_failures) + "\" errors=\"" + std::to_string(s_errors) + "\" time=\"" +
              std::to_string(s_time) + "\">\n" + cases + "  </testsuite>\n";
  }
  write_text_atomic(path, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"shadowlab grade\" tests=\"" +
                              std::to_string(tests) + "\" failures=\"" + std::to_string(failures) + "\" errors=\"" +
                              std::to_string(errors) + "\">\n" + suites + "</testsuites>\n");
}

// Gradescope's autograder results (https://gradescope-autograders.readthedocs.io, "Output format"):
// one test per lab worth 1 point, passed or not, with what to change in its output.
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

}  // namespace

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

MergeSummary merge_grades(const fs::path& out_dir, const std::vector<std::string>& expected, const std::vector<int>& labs_expected) {
  std::set<std::string> names(expected.begin(), expected.end());
  const fs::path students_dir = out_dir / "students";
  if (fs::is_directory(students_dir))
    for (const auto& e : fs::directory_iterator(students_dir))
      if (e.is_directory()) names.insert(e.path().filename().string());

  MergeSummary summary;
  std::map<std::string, int> by_status;
  for (const auto& s : kGradeStatuses) by_status[s] = 0;
  std::set<int> all_labs;
  json students = json::array();
  for (const auto& name : names) {
    const fs::path dir = students_dir / name;
    const json submission = read_json(dir / "submission.json");
    // The labs this student's grading planned (written before the first lab ran), and those recorded.
    std::set<int> planned;
    if (submission.is_object())
      for (const auto& n : submission.value("labs", json::array())) planned.insert(n.get<int>());
    std::map<int, json> records;
    if (fs::is_directory(dir))
      for (const auto& e : fs::directory_iterator(dir)) {
        const std::string file = e.path().filename().string();
        if (file.rfind("lab_", 0) != 0 || e.path().extension() != ".json" || file.find(".check.") != std::string::npos)
          continue;
        const json r = read_json(e.path());
        if (r.is_object() && r.value("schema", "") == "shadowlab-grade-lab") records[r.value("lab", -1)] = r;
      }
    if (planned.empty() && records.empty())
      planned.insert(labs_expected.begin(), labs_expected.end());
    for (int lab : planned)
      if (!records.count(lab))
        records[lab] = lab_record(lab, name, "grader_error",
                                  "no result: this lab's grading did not finish (the run was killed, or has not "
                                  "reached it); grade again to continue");
    json labs = json::array();
    int passed = 0;
    for (auto& [lab, r] : records) {
      all_labs.insert(lab);
      const std::string status = r.value("status", "grader_error");
      by_status[status]++;
      passed += status == "passed";
      summary.grader_errors += status == "grader_error";
      r.erase("schema");
      r.erase("version");
      r.erase("student");
      labs.push_back(r);
    }
    summary.labs += static_cast<int>(labs.size());
    summary.passed += passed;
    json student = {{"name", name},
                    {"source", submission.is_object() ? submission.value("source", "") : ""},
                    {"score", passed},
                    {"max_score", labs.size()},
                    {"labs", labs}};
    if (submission.is_object() && submission.contains("error")) student["error"] = submission["error"];
    students.push_back(student);
  }
  summary.students = static_cast<int>(students.size());

  json labs = json::array();
  for (int n : all_labs) {
    const Lab* l = find_lab(n);
    labs.push_back({{"lab", n}, {"slug", l ? l->slug : ""}, {"title", l ? l->title : ""},
                    {"files", l ? l->exercise_files : std::vector<std::string>{}}});
  }
  int all_passed = 0;
  for (const auto& s : students) all_passed += s["score"] == s["max_score"];
  const json report = {{"schema", "shadowlab-grade"},
                       {"version", kGradeSchemaVersion},
                       {"generated", utc_now()},
                       {"statuses", kGradeStatuses},
                       {"labs", labs},
                       {"summary",
                        {{"students", summary.students},
                         {"students_all_passed", all_passed},
                         {"labs_graded", summary.labs},
                         {"by_status", by_status}}},
                       {"students", students}};
  write_text_atomic(out_dir / "results.json", report.dump(2) + "\n");
  write_csv(out_dir / "results.csv", students);
  write_junit(out_dir / "junit.xml", students);
  summary.written = {(out_dir / "results.json").string(), (out_dir / "results.csv").string(),
                     (out_dir / "junit.xml").string()};
  for (const auto& s : students) {
    const fs::path dir = out_dir / "gradescope" / s.value("name", "");
    fs::create_directories(dir);
    write_text_atomic(dir / "results.json", gradescope_results(s).dump(2) + "\n");
  }
  summary.written.push_back((out_dir / "gradescope" / "<student>" / "results.json").string());
  return summary;
}

}  // namespace shadowlab
