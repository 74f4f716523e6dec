#include "batch_manifest.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "exit_codes.h"
#include "loom_options.h"
#include "paint_options.h"
#include "synth_options.h"

namespace meshquilt::cli {
namespace {

using nlohmann::json;

struct RawJob {
  int line = 0;
  json value;
};

[[noreturn]] void fail(const std::filesystem::path& file, int line, const std::string& problem) {
  throw InputError(file.string() + ":" + std::to_string(line) + ": " + problem, ErrorKind::bad_manifest);
}

int line_of_offset(const std::string& text, size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(std::min(offset, text.size())), '\n'));
}

// nlohmann's parse errors say "at line L, column C"; keep only what follows the position.
std::string short_parse_error(const json::parse_error& e) {
  std::string what = e.what();
  const size_t colon = what.find(": syntax error");
  if (colon != std::string::npos) what = what.substr(colon + 2);
  return what;
}

std::vector<RawJob> read_json_lines(const std::filesystem::path& file, const std::string& text) {
  std::vector<RawJob> jobs;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    try {
      jobs.push_back({number, json::parse(line)});
    } catch (const json::parse_error& e) {
      fail(file, number, "not a JSON object: " + short_parse_error(e));
    }
  }
  return jobs;
}

// Lines where the job objects of a JSON manifest start: objects directly inside the top-level
// array, or inside the "jobs" array of a top-level object. nlohmann's DOM keeps no positions, so
// this walks the (already validated) text once, tracking strings and nesting.
std::vector<int> job_start_lines(const std::string& text) {
  std::vector<int> lines;
  std::vector<char> open;
  bool in_string = false, escaped = false;
  int line = 1;
  for (char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      const bool job = c == '{' && ((open.size() == 1 && open[0] == '[') ||
                                    (open.size() == 2 && open[0] == '{' && open[1] == '['));
      if (job) lines.push_back(line);
      open.push_back(c);
    } else if (c == ']' || c == '}') {
      if (!open.empty()) open.pop_back();
    }
  }
  return lines;
}

std::vector<RawJob> read_json_document(const std::filesystem::path& file, const std::string& text) {
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(file, line_of_offset(text, e.byte > 0 ? e.byte - 1 : 0), "not JSON: " + short_parse_error(e));
  }
  json list;
  if (document.is_array()) {
    list = document;
  } else if (document.is_object()) {
    for (const auto& [key, value] : document.items())
      if (key != "jobs") fail(file, 1, "unknown key '" + key + "' (expected \"jobs\")");
    if (!document.contains("jobs") || !document["jobs"].is_array()) fail(file, 1, "expected \"jobs\": [...]");
    list = document["jobs"];
  } else {
    fail(file, 1, "expected an array of jobs or {\"jobs\": [...]}");
  }
  const std::vector<int> lines = job_start_lines(text);
  std::vector<RawJob> jobs;
  for (size_t i = 0; i < list.size(); ++i) {
    // A job that is not an object has no '{' of its own: name the line of the last one before.
    const int line = i < lines.size() ? lines[i] : (lines.empty() ? 1 : lines.back());
    jobs.push_back({line, list[i]});
  }
  return jobs;
}

std::string option_value_text(const std::filesystem::path& file, int line, const std::string& name,
                              const json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number()) return value.dump();
  fail(file, line, "option '" + name + "': expected a string or a number, got " + value.dump());
}

std::vector<std::string> option_list(const std::filesystem::path& file, int line, const json& options) {
  std::vector<std::string> list;
  if (options.is_null()) return list;
  if (options.is_array()) {
    for (const json& entry : options) list.push_back(option_value_text(file, line, entry.dump(), entry));
    return list;
  }
  if (!options.is_object()) fail(file, line, "\"options\": expected a list or an object");
  for (const auto& [key, value] : options.items()) {
    const std::string name = key.rfind('-', 0) == 0 ? key : (key.size() == 1 ? "-" : "--") + key;
    if (value.is_boolean()) {
      if (value.get<bool>()) list.push_back(name);
      continue;
    }
    list.push_back(name);
    list.push_back(option_value_text(file, line, key, value));
  }
  return list;
}

// The commands a job may run: each parses its options with a fresh CLI::App carrying the
// command's own registration and names the files they read and write.
struct JobFiles {
  std::vector<std::string> inputs, outputs;
};

template <typename Args>
JobFiles parse_with(const std::filesystem::path& file, int line, const std::string& command,
                    const std::vector<std::string>& options, const std::string& output,
                    void (*add)(CLI::App*, Args&), std::vector<std::string> (*inputs)(const Args&),
                    std::vector<std::string> (*outputs)(const Args&)) {
  Args args;
  CLI::App app{command};
  add(&app, args);
  // The job's output goes in as --output, so that commands requiring one parse; an output among
  // the options is refused.
  std::vector<std::string> list = options;
  const bool output_given = std::find_if(list.begin(), list.end(), [](const std::string& a) {
                              return a == "-o" || a == "--output" || a.rfind("--output=", 0) == 0;
                            }) != list.end();
  if (output_given) fail(file, line, "give the output as the job's \"output\", not as an option");
  list.push_back("--output");
  list.push_back(output);
  std::vector<std::string> reversed(list.rbegin(), list.rend());  // CLI11 consumes from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    fail(file, line, e.what());
  } catch (const Error& e) {
    fail(file, line, message(e));
  }
  if (app.get_option("--progress")->count() > 0) fail(file, line, "--progress is set by batch, not per job");
  return {inputs(args), outputs(args)};
}

JobFiles parse_job_options(const std::filesystem::path& file, int line, const std::string& command,
                           const std::vector<std::string>& options, const std::string& output) {
  if (command == "synth")
    return parse_with<SynthArgs>(file, line, command, options, output, add_synth_options, synth_input_files,
                                 synth_output_files);
  if (command == "paint")
    return parse_with<PaintArgs>(file, line, command, options, output, add_paint_options, paint_input_files,
                                 paint_output_files);
  if (command == "relief")
    return parse_with<ReliefArgs>(file, line, command, options, output, add_relief_options, relief_input_files,
                                  relief_output_files);
  if (command == "loom")
    return parse_with<LoomArgs>(file, line, command, options, output, add_loom_options, loom_input_files,
                                loom_output_files);
  fail(file, line, "\"command\": expected synth, paint, relief or loom, got '" + command + "'");
}

BatchJob make_job(const Manifest& manifest, size_t index, const RawJob& raw) {
  const std::filesystem::path& file = manifest.file;
  if (!raw.value.is_object()) fail(file, raw.line, "a job must be an object {\"output\": ..., \"options\": ...}");
  for (const auto& [key, value] : raw.value.items())
    if (key != "command" && key != "output" && key != "options")
      fail(file, raw.line, "unknown key '" + key + "' (expected \"command\", \"output\" and \"options\")");
  if (raw.value.contains("command") && !raw.value["command"].is_string())
    fail(file, raw.line, "\"command\": expected synth, paint, relief or loom");
  if (!raw.value.contains("output") || !raw.value["output"].is_string() ||
      raw.value["output"].get<std::string>().empty())
    fail(file, raw.line, "\"output\": expected the output mesh's path");
  BatchJob job;
  job.index = index;
  job.line = raw.line;
  job.command = raw.value.value("command", "synth");
  job.output = raw.value["output"].get<std::string>();
  job.options = option_list(file, raw.line, raw.value.value("options", json()));
  JobFiles files = parse_job_options(file, raw.line, job.command, job.options, job.output);
  job.inputs = std::move(files.inputs);
  job.outputs = std::move(files.outputs);
  for (const std::string& input : job.inputs) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(manifest.resolve(input), error)) {
      job.problem = input + ": cannot open: " + std::strerror(ENOENT);
      break;
    }
  }
  return job;
}

}  // namespace

std::vector<std::string> BatchJob::arguments() const {
  std::vector<std::string> arguments = options;
  arguments.push_back("-o");
  arguments.push_back(output);
  return arguments;
}

std::filesystem::path Manifest::resolve(const std::string& path) const {
  return (folder / std::filesystem::path(path)).lexically_normal();
}

std::string Manifest::where(const BatchJob& job) const { return file.string() + ":" + std::to_string(job.line); }

Manifest read_manifest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw IoError(ErrorKind::file_unreadable,
                  file.string() + ": cannot open: " + std::strerror(in ? EISDIR : errno));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();

  Manifest manifest;
  manifest.file = file;
  manifest.folder = std::filesystem::absolute(file).parent_path().lexically_normal();
  const std::vector<RawJob> raw =
      file.extension() == ".json" ? read_json_document(file, text) : read_json_lines(file, text);
  if (raw.empty()) fail(file, 1, "no jobs");

  std::map<std::filesystem::path, int> writers;  // every output file -> the line of its job
  for (size_t i = 0; i < raw.size(); ++i) {
    BatchJob job = make_job(manifest, i, raw[i]);
    for (const std::string& output : job.outputs) {
      const auto [it, fresh] = writers.emplace(manifest.resolve(output), job.line);
      if (!fresh) fail(file, job.line, output + " is also written by the job on line " + std::to_string(it->second));
    }
    manifest.jobs.push_back(std::move(job));
  }
  return manifest;
}

}  // namespace meshquilt::cli
