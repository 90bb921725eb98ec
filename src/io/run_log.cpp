#include "io/run_log.hpp"

#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace rouleau {

// The stream's state follows the terminal alone: a log that can no longer be written (a
// full disk) must not silence stderr.
int RunLog::Tee::overflow(int c) {
  if (c == traits_type::eof()) return traits_type::not_eof(c);
  second_->sputc(static_cast<char>(c));
  return first_->sputc(static_cast<char>(c));
}

std::streamsize RunLog::Tee::xsputn(const char* s, std::streamsize n) {
  second_->sputn(s, n);
  return first_->sputn(s, n);
}

int RunLog::Tee::sync() {
  second_->pubsync();
  return first_->pubsync();
}

RunLog::RunLog(const std::string& path, const std::string& first_line, bool append)
    : stderr_buffer_(std::cerr.rdbuf()), terminal_(stderr_buffer_) {
  // A segment is set off from the one before it by an empty line (none in a new file).
  std::error_code status;
  const bool continues = append && std::filesystem::file_size(path, status) > 0 && !status;
  file_.open(path, append ? std::ios::app : std::ios::trunc);
  if (!file_) throw std::runtime_error(path + ": cannot open the run's log for writing");
  file_ << (continues ? "\n" : "") << first_line << "\n" << std::flush;
  tee_ = std::make_unique<Tee>(stderr_buffer_, file_.rdbuf());
  std::cerr.rdbuf(tee_.get());
}

RunLog::~RunLog() {
  std::cerr.rdbuf(stderr_buffer_);
  std::cerr.clear();
  file_.flush();
}

}  // namespace rouleau
