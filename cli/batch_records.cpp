#include "batch_records.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>

#include "atomic_file.h"
#include "core/error.h"
#include "sha256.h"

#ifndef MESHQUILT_VERSION
#define MESHQUILT_VERSION "unknown"
#endif

namespace meshquilt::cli {
namespace {

using nlohmann::json;

std::string job_key(const Manifest& manifest, const BatchJob& job) {
  const std::filesystem::path output = manifest.resolve(job.output);
  std::string name = output.filename().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return name + "-" + sha256_hex(output.string()).substr(0, 12);
}

std::string now_utc() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "";
  return name;
}

json hashes(const Manifest& manifest, const std::vector<std::string>& files) {
  json map = json::object();
  for (const std::string& file : files) map[file] = sha256_file(manifest.resolve(file));
  return map;
}

std::optional<json> read_json(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  try {
    return json::parse(text.str());
  } catch (const json::exception&) {
    return std::nullopt;  // records are written atomically; a broken one is treated as absent
  }
}

void remove_file(const std::filesystem::path& file) {
  std::error_code error;
  std::filesystem::remove(file, error);
  if (error) throw IoError(ErrorKind::write_failed, file.string() + ": cannot remove: " + error.message());
}

json base_record(const BatchJob& job) {
  return {{"meshquilt", meshquilt_version()},
          {"job", job.index},
          {"line", job.line},
          {"output", job.output},
          {"command", job.command},
          {"arguments", job.arguments()},
          {"host", host_name()},
          {"finished_at", now_utc()}};
}

bool lock_is_held(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return held;
}

}  // namespace

std::string meshquilt_version() { return MESHQUILT_VERSION; }

std::filesystem::path records_folder(const Manifest& manifest) {
  return manifest.folder / (manifest.file.filename().string() + ".batch");
}

JobFiles job_files(const Manifest& manifest, const BatchJob& job) {
  const std::filesystem::path base = records_folder(manifest) / job_key(manifest, job);
  return JobFiles{base.string() + ".done.json", base.string() + ".failed.json", base.string() + ".log",
                  base.string() + ".lock"};
}

const char* job_state_name(JobState state) {
  switch (state) {
    case JobState::done: return "done";
    case JobState::failed: return "failed";
    case JobState::running: return "running";
    case JobState::missing: return "missing";
    case JobState::stale: return "stale";
  }
  return "?";
}

void record_completion(const Manifest& manifest, const BatchJob& job, const json& summary, double seconds) {
  const JobFiles files = job_files(manifest, job);
  json record = base_record(job);
  record["inputs"] = hashes(manifest, job.inputs);
  record["outputs"] = hashes(manifest, job.outputs);
  record["seconds"] = seconds;
  record["summary"] = summary;
  write_text_atomic(files.done, record.dump(2) + "\n");
  remove_file(files.failed);
}

void record_failure(const Manifest& manifest, const BatchJob& job, int exit_code, int signal, const std::string& error,
                    double seconds) {
  const JobFiles files = job_files(manifest, job);
  json record = base_record(job);
  record["exit_code"] = exit_code;
  record["signal"] = signal;
  record["error"] = error;
  record["seconds"] = seconds;
  remove_file(files.done);
  write_text_atomic(files.failed, record.dump(2) + "\n");
}

void forget_completion(const Manifest& manifest, const BatchJob& job) { remove_file(job_files(manifest, job).done); }

bool completion_matches(const Manifest& manifest, const BatchJob& job, std::string* why) {
  auto say = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  const std::optional<json> record = read_json(job_files(manifest, job).done);
  if (!record || !record->is_object()) return say("no completion record");
  if (record->value("meshquilt", "") != meshquilt_version())
    return say("made by meshquilt " + record->value("meshquilt", "?") + ", this is " + meshquilt_version());
  if (record->value("command", "synth") != job.command) return say("command changed");
  if ((*record)["arguments"] != json(job.arguments())) return say("options changed");
  for (const auto& [group, files] : {std::pair{"inputs", job.inputs}, std::pair{"outputs", job.outputs}}) {
    const json& recorded = (*record)[group];
    if (!recorded.is_object() || recorded.size() != files.size()) return say(std::string(group) + " changed");
    for (const std::string& file : files) {
      const std::filesystem::path path = manifest.resolve(file);
      std::error_code error;
      if (!std::filesystem::is_regular_file(path, error)) return say(file + " is missing");
      if (!recorded.contains(file) || recorded[file] != sha256_file(path)) return say(file + " changed");
    }
  }
  return true;
}

JobStatus job_status(const Manifest& manifest, const BatchJob& job) {
  const JobFiles files = job_files(manifest, job);
  JobStatus status;
  if (lock_is_held(files.lock)) {
    status.state = JobState::running;
    return status;
  }
  std::string why;
  if (completion_matches(manifest, job, &why)) {
    status.state = JobState::done;
    status.record = *read_json(files.done);
    return status;
  }
  if (std::filesystem::exists(files.done)) {
    status.state = JobState::stale;
    status.detail = why;
    return status;
  }
  const std::optional<json> failure = read_json(files.failed);
  if (failure && failure->is_object() && failure->value("command", "synth") == job.command &&
      (*failure)["arguments"] == json(job.arguments())) {
    status.state = JobState::failed;
    status.record = *failure;
    status.detail = failure->value("error", "");
  }
  return status;
}

std::optional<JobLock> JobLock::try_acquire(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError(ErrorKind::write_failed, file.string() + ": cannot open: " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK) return std::nullopt;
    throw IoError(ErrorKind::write_failed, file.string() + ": cannot lock: " + std::strerror(error));
  }
  return JobLock(fd);
}

JobLock::~JobLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace meshquilt::cli
