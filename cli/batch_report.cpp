#include "batch_report.h"

#include <cstdio>
#include <vector>

#include <nlohmann/json.hpp>

#include "batch_records.h"
#include "core/error.h"

namespace meshquilt::cli {
namespace {

using nlohmann::json;

// The stats figures a report shows, in its columns' order.
const char* const kFigures[] = {"faces", "elements", "dropped_elements", "holes", "refused_merges"};

struct Row {
  const BatchJob* job;
  JobStatus status;
  double seconds = 0.0;
  json figures = json::object();
};

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string number_text(const json& value) { return value.is_number() ? value.dump() : ""; }

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", seconds);
  return text;
}

}  // namespace

ReportFormat parse_report_format(const std::string& text) {
  if (text == "table") return ReportFormat::table;
  if (text == "json") return ReportFormat::json;
  if (text == "csv") return ReportFormat::csv;
  throw InputError("--format: expected table, json or csv, got '" + text + "'", ErrorKind::invalid_option);
}

ReportTotals write_report(const Manifest& manifest, ReportFormat format, std::ostream& out) {
  std::vector<Row> rows;
  ReportTotals totals;
  json sums = json::object();
  double total_seconds = 0.0;
  for (const BatchJob& job : manifest.jobs) {
    Row row{&job, job_status(manifest, job)};
    const json& record = row.status.record;
    if (record.is_object()) row.seconds = record.value("seconds", 0.0);
    ++totals.jobs;
    switch (row.status.state) {
      case JobState::done: {
        ++totals.done;
        total_seconds += row.seconds;
        const json summary = record.value("summary", json::object());
        for (const char* figure : kFigures)
          if (summary.contains(figure) && summary[figure].is_number()) {
            row.figures[figure] = summary[figure];
            sums[figure] = sums.value(figure, 0.0) + summary[figure].get<double>();
          }
        break;
      }
      case JobState::failed: ++totals.failed; break;
      case JobState::running: ++totals.running; break;
      case JobState::missing:
      case JobState::stale: ++totals.missing; break;
    }
    rows.push_back(std::move(row));
  }

  if (format == ReportFormat::json) {
    json jobs = json::array();
    for (const Row& row : rows) {
      json entry = {{"job", row.job->index},     {"line", row.job->line},
                    {"command", row.job->command}, {"output", row.job->output},
                    {"status", job_state_name(row.status.state)}, {"seconds", row.seconds}};
      entry.update(row.figures);
      if (!row.status.detail.empty()) entry["detail"] = row.status.detail;
      jobs.push_back(entry);
    }
    json summary = {{"jobs", totals.jobs},       {"done", totals.done},       {"failed", totals.failed},
                    {"running", totals.running}, {"missing", totals.missing}, {"seconds", total_seconds}};
    for (const auto& [figure, sum] : sums.items()) summary[figure] = sum;
    out << json{{"manifest", manifest.file.string()}, {"jobs", jobs}, {"totals", summary}}.dump(2) << "\n";
    return totals;
  }

  if (format == ReportFormat::csv) {
    out << "job,line,output,status,seconds";
    for (const char* figure : kFigures) out << "," << figure;
    out << ",detail\n";
    for (const Row& row : rows) {
      out << row.job->index << "," << row.job->line << "," << csv_field(row.job->output) << ","
          << job_state_name(row.status.state) << "," << seconds_text(row.seconds);
      for (const char* figure : kFigures) out << "," << number_text(row.figures.value(figure, json()));
      out << "," << csv_field(row.status.detail) << "\n";
    }
    return totals;
  }

  char line[512];
  std::snprintf(line, sizeof line, "%4s %5s  %-8s %8s %9s %8s %7s %5s %7s  %s\n", "job", "line", "status", "seconds",
                "faces", "elements", "dropped", "holes", "refused", "output");
  out << line;
  for (const Row& row : rows) {
    auto figure = [&](const char* name) { return number_text(row.figures.value(name, json())); };
    std::snprintf(line, sizeof line, "%4zu %5d  %-8s %8s %9s %8s %7s %5s %7s  %s", row.job->index, row.job->line,
                  job_state_name(row.status.state), seconds_text(row.seconds).c_str(), figure("faces").c_str(),
                  figure("elements").c_str(), figure("dropped_elements").c_str(), figure("holes").c_str(),
                  figure("refused_merges").c_str(), row.job->output.c_str());
    out << line;
    if (!row.status.detail.empty()) out << "  (" << row.status.detail << ")";
    out << "\n";
  }
  auto sum = [&](const char* name) { return sums.contains(name) ? json(sums[name].get<long long>()).dump() : ""; };
  std::snprintf(line, sizeof line, "%4s %5s  %-8s %8s %9s %8s %7s %5s %7s  %zu done, %zu failed, %zu running, %zu missing\n",
                "all", "", "", seconds_text(total_seconds).c_str(), sum("faces").c_str(), sum("elements").c_str(),
                sum("dropped_elements").c_str(), sum("holes").c_str(), sum("refused_merges").c_str(), totals.done,
                totals.failed, totals.running, totals.missing);
  out << line;
  return totals;
}

}  // namespace meshquilt::cli
