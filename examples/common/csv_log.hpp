// The examples' CSV files: the training log fed by dpgen::train()'s per-iteration observer
// (TrainOptions::callback). The runtime itself writes no files; this is where the examples do.
#pragma once

#include "dpgen/train.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace dpgen_examples {

/// A CSV log with the header `iter,loss,grad_norm,seconds` and one row per training iteration
/// (iter 0 being the state before the first update), or with a header of the caller's and rows
/// given as text (line()). Rows go to `<path>.partial`, flushed line
/// by line; close() (or the destructor, e.g. while an exception unwinds) renames that file to
/// `path`, replacing an older log. So `path` only ever holds a finished run's complete log
/// (ending with the offending row when the run stopped on NaN/Inf), and a process killed
/// mid-run leaves `<path>.partial`, never a half-written or stale file that looks finished.
/// An empty path makes a log that writes nothing.
class CsvLog {
public:
  explicit CsvLog(std::string path) : CsvLog(std::move(path), "iter,loss,grad_norm,seconds") {}
  CsvLog(std::string path, const std::string& header)
      : path_(std::move(path)), partial_(path_ + ".partial") {
    if (path_.empty())
      return;
    out_.open(partial_, std::ios::out | std::ios::trunc);
    if (!out_)
      throw std::runtime_error("csv log: cannot open '" + partial_ + "' for writing");
    out_ << header << '\n' << std::flush;
  }
  CsvLog(const CsvLog&) = delete;
  CsvLog& operator=(const CsvLog&) = delete;
  /// Publishes what was logged if close() was not called (quietly: a destructor cannot throw;
  /// a failed rename is reported on stderr).
  ~CsvLog() {
    if (out_.is_open()) {
      out_.close();
      std::error_code error;
      std::filesystem::rename(partial_, path_, error);
      if (error)
        std::fprintf(stderr, "warning: csv log: cannot rename '%s' to '%s': %s\n",
                     partial_.c_str(), path_.c_str(), error.message().c_str());
    }
  }

  /// Appends one row (flushed at once). Throws std::runtime_error when writing fails.
  void row(const dpgen::TrainProgress& p) {
    if (!out_.is_open())
      return;
    char text[128];
    std::snprintf(text, sizeof text, "%d,%.17g,%.17g,%.9g", p.iteration, p.loss, p.grad_norm,
                  p.seconds);
    line(text);
  }

  /// Appends one row given as text, without its line end (flushed at once). Throws
  /// std::runtime_error when writing fails.
  void line(const std::string& text) {
    if (!out_.is_open())
      return;
    out_ << text << '\n' << std::flush;
    if (!out_)
      throw std::runtime_error("csv log: writing '" + partial_ + "' failed");
  }

  /// Finishes the log: renames `<path>.partial` to `path`. Further rows are ignored. Throws
  /// std::runtime_error when the rename fails.
  void close() {
    if (!out_.is_open())
      return;
    out_.close();
    std::error_code error;
    std::filesystem::rename(partial_, path_, error);
    if (error)
      throw std::runtime_error("csv log: cannot rename '" + partial_ + "' to '" + path_ +
                               "': " + error.message());
  }

  const std::string& path() const { return path_; }

private:
  std::string path_, partial_;
  std::ofstream out_;
};

/// A number as a CSV field that reads back to the same double ("%.17g": 0.1 is
/// 0.10000000000000001).
inline std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

/// Hooks a CsvLog at `path` (nothing when empty) into `options`' observer: each row is logged,
/// then passed on to the observer already there. The log is published when the last copy of
/// `options` is destroyed (a temporary TrainOptions passed to train(): right after train() returns
/// or throws), or earlier by calling close() on the returned log.
inline std::shared_ptr<CsvLog> attach_csv_log(dpgen::TrainOptions& options,
                                              const std::string& path) {
  auto log = std::make_shared<CsvLog>(path);
  if (path.empty())
    return log;
  options.callback = [log, previous = std::move(options.callback)](const dpgen::TrainProgress& p) {
    log->row(p);
    if (previous)
      previous(p);
  };
  return log;
}

} // namespace dpgen_examples
