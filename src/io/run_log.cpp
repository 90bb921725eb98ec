#include "io/run_log.hpp"

#include <iostream>
#include <stdexcept>

namespace rouleau {

int RunLog::Tee::overflow(int c) {
  if (c == traits_type::eof()) return traits_type::not_eof(c);
  const int first = first_->sputc(static_cast<char>(c));
  const int second = second_->sputc(static_cast<char>(c));
  return first == traits_type::eof() || second == traits_type::eof() ? traits_type::eof() : c;
}

std::streamsize RunLog::Tee::xsputn(const char* s, std::streamsize n) {
  const std::streamsize first = first_->sputn(s, n);
  const std::streamsize second = second_->sputn(s, n);
  return std::min(first, second);
}

int RunLog::Tee::sync() {
  const int first = first_->pubsync();
  const int second = second_->pubsync();
  return first == 0 && second == 0 ? 0 : -1;
}

RunLog::RunLog(const std::string& path, const std::string& first_line, bool append)
    : file_(path, append ? std::ios::app : std::ios::trunc), stderr_buffer_(std::cerr.rdbuf()),
      terminal_(stderr_buffer_) {
  if (!file_) throw std::runtime_error("rouleau::RunLog: " + path + ": cannot open the run's log for writing");
  file_ << (append ? "\n" : "") << first_line << "\n" << std::flush;
  tee_ = std::make_unique<Tee>(stderr_buffer_, file_.rdbuf());
  std::cerr.rdbuf(tee_.get());
}

RunLog::~RunLog() {
  std::cerr.rdbuf(stderr_buffer_);
  file_.flush();
}

}  // namespace rouleau
