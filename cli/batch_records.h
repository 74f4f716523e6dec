#pragma once
//! What a batch remembers about each job, in `MANIFEST.batch/` beside the manifest: a completion
//! record (KEY.done.json: meshquilt version, the command and its arguments, SHA-256 of the inputs and outputs,
//! the stats summary), a failure record (KEY.failed.json: exit code and error line), the job's
//! stderr (KEY.log) and a lock file (KEY.lock) that the running job holds with flock. KEY is
//! the output's file name plus a hash of its full path. Records are written atomically, after
//! the outputs, so a job killed at any moment leaves no completion record and is redone.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "batch_manifest.h"

namespace meshquilt::cli {

//! The version written into completion records; a record of another version is redone.
std::string meshquilt_version();

struct JobFiles {
  std::filesystem::path done;     //!< completion record
  std::filesystem::path failed;   //!< failure record
  std::filesystem::path log;      //!< stderr of the last run
  std::filesystem::path lock;     //!< flock'ed while the job runs
};

//! The folder of a manifest's records: "MANIFEST.batch" beside it.
std::filesystem::path records_folder(const Manifest& manifest);
JobFiles job_files(const Manifest& manifest, const BatchJob& job);

enum class JobState { done, failed, running, missing, stale };
const char* job_state_name(JobState state);

struct JobStatus {
  JobState state = JobState::missing;
  nlohmann::json record;  //!< the completion or failure record read, or null
  std::string detail;     //!< failed: the error; stale: what no longer matches
};

//! Writes KEY.done.json after a successful run (hashing inputs and outputs now) and removes the
//! failure record. `summary` is the command's JSON summary. \throw IoError naming the file.
void record_completion(const Manifest& manifest, const BatchJob& job, const nlohmann::json& summary, double seconds);

//! Writes KEY.failed.json and removes any completion record. \throw IoError naming the file.
void record_failure(const Manifest& manifest, const BatchJob& job, int exit_code, int signal,
                    const std::string& error, double seconds);

//! Removes the job's completion record (before it runs again). \throw IoError.
void forget_completion(const Manifest& manifest, const BatchJob& job);

//! Whether the job's completion record matches it now: version, arguments, the inputs' and
//! outputs' hashes. `why` (optional) says what does not.
bool completion_matches(const Manifest& manifest, const BatchJob& job, std::string* why = nullptr);

//! The job's state as the records and its lock say; never blocks or creates files.
JobStatus job_status(const Manifest& manifest, const BatchJob& job);

//! An exclusive flock on a job's lock file, released when destroyed. The descriptor is
//! close-on-exec; a child that must keep the lock alive dup()s it.
class JobLock {
 public:
  //! The lock, or nullopt when another process holds it. \throw IoError(write_failed).
  static std::optional<JobLock> try_acquire(const std::filesystem::path& file);
  JobLock(JobLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  JobLock& operator=(JobLock&& other) noexcept {
    std::swap(fd_, other.fd_);
    return *this;
  }
  ~JobLock();
  int fd() const { return fd_; }

 private:
  explicit JobLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace meshquilt::cli
