// A run folder holds one run: a new run refuses a folder that holds files unless told to
// empty it (and then empties only a run's folder), and a restart refuses a folder whose
// files carry different run ids. The functions in process; the executable's refusals are
// in test_run_case.cpp (RunFolder).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "io/hdf5_file.hpp"
#include "io/provenance.hpp"
#include "io/run_folder.hpp"
#include "temporary_folder.hpp"
#include "util/errors.hpp"

namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// An HDF5 file whose provenance carries `run_id` (none when empty), as a run's fields and
// checkpoints do.
void write_run_file(const fs::path& path, const std::string& run_id) {
  fs::create_directories(path.parent_path());
  rouleau::Provenance provenance;
  if (!run_id.empty()) provenance.set("run_id", run_id);
  rouleau::write_hdf5_file_atomically(path.string(), "test", provenance, [](const rouleau::Hdf5File&) {});
}

// The reason of the InputError that `f` throws, and its key in `key`; "" when it throws none.
template <class F>
std::string input_error(F&& f, std::string* key = nullptr) {
  try {
    f();
  } catch (const rouleau::InputError& error) {
    if (key) *key = error.key();
    return error.reason();
  }
  return "";
}

TEST(RunFolder, RunIdsAreSixteenHexDigitsAndDiffer) {
  std::set<std::string> ids;
  for (int i = 0; i < 100; ++i) {
    const std::string id = rouleau::new_run_id();
    EXPECT_EQ(id.size(), 16u);
    EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos) << id;
    ids.insert(id);
  }
  EXPECT_EQ(ids.size(), 100u);
}

TEST(RunFolder, NewRunTakesAMissingOrEmptyFolder) {
  const fs::path missing = rouleau::testing::temporary_folder_path("run_folder_missing");
  fs::remove_all(missing);
  rouleau::prepare_new_run_folder((missing / "nested").string(), false);
  EXPECT_TRUE(fs::is_directory(missing / "nested"));
  rouleau::prepare_new_run_folder((missing / "nested").string(), false);  // empty: taken again
}

TEST(RunFolder, NewRunRefusesAFileAndAFolderThatHoldsFiles) {
  const fs::path root = rouleau::testing::fresh_temporary_folder("run_folder_refusals");
  write_text(root / "a_file", "x");
  std::string key;
  EXPECT_NE(input_error([&] { rouleau::prepare_new_run_folder((root / "a_file").string(), true); }, &key)
                .find("names a file"),
            std::string::npos);
  EXPECT_EQ(key, "--out");

  // An earlier run: refused, naming its run id and the way out; nothing removed.
  const fs::path earlier = root / "earlier";
  write_text(earlier / "run.log", rouleau::run_log_first_line("00000000000000aa", "case a") + "\nmore\n");
  write_text(earlier / "diagnostics.csv", "step\n0\n");
  write_text(earlier / "paper_checks.csv", "figure,statement,metric,value,relation,threshold,unit,met\n");
  write_text(earlier / "figures" / "gaps.png", "png");
  write_run_file(earlier / "fields_000010.h5", "00000000000000aa");
  write_text(earlier / "fields_cells.xdmf", "<Xdmf/>");
  const std::string reason = input_error([&] { rouleau::prepare_new_run_folder(earlier.string(), false); });
  EXPECT_NE(reason.find("an earlier run (run id 00000000000000aa)"), std::string::npos) << reason;
  EXPECT_NE(reason.find("--overwrite"), std::string::npos) << reason;
  EXPECT_TRUE(fs::exists(earlier / "diagnostics.csv"));
  EXPECT_TRUE(rouleau::holds_a_run(earlier.string()));

  // With --overwrite it is emptied, sub-folders too.
  write_run_file(earlier / "checkpoints" / "checkpoint_000000001.h5", "00000000000000aa");
  rouleau::prepare_new_run_folder(earlier.string(), true);
  EXPECT_TRUE(fs::is_directory(earlier));
  EXPECT_TRUE(fs::is_empty(earlier));

  // A folder no run wrote: refused even with --overwrite, and left as it was; so is a
  // folder with a figures/ folder and .h5 files but no run's log or resolved case (a case's
  // own folder, a home folder).
  const fs::path notes = root / "notes";
  write_text(notes / "thesis.tex", "chapter 1");
  write_text(notes / "figures" / "plot.png", "png");
  write_run_file(notes / "data.h5", "");
  for (const bool overwrite : {false, true}) {
    const std::string refusal = input_error([&] { rouleau::prepare_new_run_folder(notes.string(), overwrite); });
    EXPECT_NE(refusal.find("holds files that no rouleau run wrote (data.h5, ...)"), std::string::npos) << refusal;
    EXPECT_EQ(refusal.find("--overwrite"), std::string::npos) << refusal;
  }
  EXPECT_TRUE(fs::exists(notes / "thesis.tex"));
  EXPECT_FALSE(rouleau::holds_a_run(notes.string()));

  // A run's folder with one file a run does not write: --overwrite removes nothing.
  const fs::path mixed = root / "mixed";
  write_text(mixed / "run.log", rouleau::run_log_first_line("00000000000000cc", "case c") + "\n");
  write_text(mixed / "diagnostics.csv", "step\n0\n");
  write_run_file(mixed / "checkpoints" / "checkpoint_000000001.h5", "00000000000000cc");
  write_text(mixed / "checkpoints" / "my_notes.txt", "keep me");
  std::string refusal = input_error([&] { rouleau::prepare_new_run_folder(mixed.string(), true); });
  EXPECT_NE(refusal.find("also holds " + (mixed / "checkpoints" / "my_notes.txt").string()), std::string::npos)
      << refusal;
  EXPECT_TRUE(fs::exists(mixed / "diagnostics.csv"));
  EXPECT_TRUE(fs::exists(mixed / "checkpoints" / "my_notes.txt"));
  fs::remove(mixed / "checkpoints" / "my_notes.txt");
  write_text(mixed / "thesis.tex", "chapter 2");
  refusal = input_error([&] { rouleau::prepare_new_run_folder(mixed.string(), true); });
  EXPECT_NE(refusal.find("also holds " + (mixed / "thesis.tex").string()), std::string::npos) << refusal;
  EXPECT_TRUE(fs::exists(mixed / "run.log"));

  // A folder inside a run's folder is refused: it would mix with that run's files.
  key.clear();
  refusal = input_error([&] { rouleau::prepare_new_run_folder((mixed / "checkpoints" / "new").string(), false); }, &key);
  EXPECT_EQ(key, "--out");
  EXPECT_NE(refusal.find("lies inside the folder of a run"), std::string::npos) << refusal;
  EXPECT_FALSE(fs::exists(mixed / "checkpoints" / "new"));
}

TEST(RunFolder, RestartTakesAFolderOfOneRunAndRefusesAMixture) {
  const fs::path root = rouleau::testing::fresh_temporary_folder("run_folder_restart");
  const std::string a = "00000000000000aa", b = "00000000000000bb";
  write_text(root / "run.log", rouleau::run_log_first_line(a, "case a, started then") + "\n");
  write_run_file(root / "fields_mesh.h5", a);
  write_run_file(root / "fields_000001.h5", a);
  write_run_file(root / "checkpoints" / "checkpoint_000000001.h5", a);
  write_text(root / "checkpoints" / "damaged.h5", "not HDF5");  // left to the checkpoint reader
  EXPECT_EQ(rouleau::single_run_id(root.string()), a);
  EXPECT_EQ(rouleau::run_ids_in_folder(root.string()).size(), 4u);

  // Another run's checkpoint among them.
  write_run_file(root / "checkpoints" / "checkpoint_000000002.h5", b);
  std::string key;
  const std::string reason = input_error([&] { rouleau::single_run_id(root.string()); }, &key);
  EXPECT_EQ(key, "--restart");
  EXPECT_NE(reason.find("different runs"), std::string::npos) << reason;
  EXPECT_NE(reason.find("checkpoint_000000002.h5 (run " + b + ")"), std::string::npos) << reason;

  // A file of an earlier version (no run id) beside files with one is a mixture too.
  fs::remove(root / "checkpoints" / "checkpoint_000000002.h5");
  write_run_file(root / "fields_000002.h5", "");
  EXPECT_NE(input_error([&] { rouleau::single_run_id(root.string()); }).find("no run id"), std::string::npos);
  // A folder wholly of an earlier version restarts as before.
  const fs::path old = rouleau::testing::fresh_temporary_folder("run_folder_old");
  write_run_file(old / "fields_mesh.h5", "");
  write_run_file(old / "checkpoints" / "checkpoint_000000000.h5", "");
  EXPECT_EQ(rouleau::single_run_id(old.string()), "");
}

}  // namespace
