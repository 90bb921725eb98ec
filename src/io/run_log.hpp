#pragma once
// The run's log: while a RunLog lives, everything the process writes to std::cerr also goes
// to the run folder's run.log, so the folder keeps what the run said (the case, the mesh,
// the solver's choices, warnings, the stage times, the error that stopped it). A restart
// appends to the log of the run it continues. The progress line, redrawn in place on a
// terminal, goes to terminal() alone; the log gets its own lines from file().
// Host-only: includes no Kokkos header.
#include <fstream>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

namespace rouleau {

class RunLog {
 public:
  // Opens `path`: a new file that starts with `first_line`, or (`append`) the existing one,
  // continued after an empty line and `first_line`. Throws std::runtime_error naming the
  // path when it cannot be opened. Writing to stderr goes on when the log cannot be written.
  RunLog(const std::string& path, const std::string& first_line, bool append);
  // Gives std::cerr back its own buffer.
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  // stderr alone (the progress line on a terminal), and the log file alone.
  std::ostream& terminal() { return terminal_; }
  std::ostream& file() { return file_; }

 private:
  class Tee : public std::streambuf {
   public:
    Tee(std::streambuf* first, std::streambuf* second) : first_(first), second_(second) {}

   protected:
    int overflow(int c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    int sync() override;

   private:
    std::streambuf* first_;
    std::streambuf* second_;
  };

  std::ofstream file_;
  std::streambuf* stderr_buffer_;
  std::ostream terminal_;
  std::unique_ptr<Tee> tee_;
};

}  // namespace rouleau
