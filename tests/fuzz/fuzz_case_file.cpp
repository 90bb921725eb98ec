// libFuzzer target: the case-file loader (config/load_case.hpp) on arbitrary bytes.
// Every input must either load or be refused with an InputError that names the file;
// any other exception, a crash, a hang, a leak or a sanitizer finding is a bug. A case
// that loads must also survive the trip through its resolved form, which is what a
// checkpoint stores and a restart reads: resolved → loaded → resolved gives the same text.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "config/resolved_case.hpp"
#include "util/errors.hpp"

namespace {
[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_case_file: %s\n", what.c_str());
  std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rouleau::CaseConfig config;
  try {
    config = rouleau::load_case_text(text, "fuzz.toml");
  } catch (const rouleau::InputError& refused) {
    if (std::string(refused.what()).find("fuzz.toml") == std::string::npos)
      fail(std::string("a refusal that does not name the file: ") + refused.what());
    return 0;
  }
  const std::string resolved = rouleau::resolved_case_toml(config, rouleau::derive_quantities(config));
  rouleau::CaseConfig again;
  try {
    again = rouleau::load_case_text(resolved, "fuzz.toml");  // the same name: the text says where it came from
  } catch (const rouleau::InputError& refused) {
    fail(std::string("the resolved form of an accepted case is refused: ") + refused.what() + "\n" + resolved);
  }
  const std::string resolved_again = rouleau::resolved_case_toml(again, rouleau::derive_quantities(again));
  if (resolved_again != resolved) fail("the resolved form changes when loaded again:\n" + resolved + "\n---\n" + resolved_again);
  return 0;
}
