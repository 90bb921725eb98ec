// Output layer: provenance, XDMF+HDF5 time series, diagnostics CSV. Every dataset written is
// read back with the HDF5 C API and compared bit for bit; the .xdmf is parsed and each of its
// HDF5 references is checked against the file it names.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/checkpoint_file.hpp"
#include "io/diagnostics_table.hpp"
#include "io/provenance.hpp"
#include "io/xdmf_writer.hpp"
#include "hdf5_reading.hpp"
#include "rouleau_version.hpp"

namespace fs = std::filesystem;
using namespace rouleau;

namespace {

// ---- a fresh folder per test, removed when the test passes

class IoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() /
                 ("rouleau_test_io_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(directory_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(directory_);
  }
  std::string path(const std::string& name) const { return (directory_ / name).string(); }
  // Every regular file in the folder, by name.
  std::set<std::string> files() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_)) names.insert(entry.path().filename().string());
    return names;
  }
  std::string read_text(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  fs::path directory_;
};

// ---- meshes: 2x2x2 hexahedra on [0,1]^3 and the unit cube split into 6 tetrahedra

MeshDescription hex_mesh_2x2x2() {
  MeshDescription mesh{"fluid", CellType::hexahedron8, {}, {}};
  const auto node = [](int i, int j, int k) { return static_cast<long long>(i + 3 * (j + 3 * k)); };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) mesh.coordinates.insert(mesh.coordinates.end(), {0.5 * i, 0.5 * j, 0.5 * k});
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        mesh.connectivity.insert(mesh.connectivity.end(),
                                 {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                                  node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                                  node(i, j + 1, k + 1)});
  return mesh;
}

// Kuhn subdivision around the diagonal 0-6 (VTK hexahedron numbering of the cube's corners).
MeshDescription tet_mesh_cube() {
  MeshDescription mesh{"cells", CellType::tetrahedron4,
                       {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1},
                       {0, 1, 2, 6, 0, 2, 3, 6, 0, 3, 7, 6, 0, 7, 4, 6, 0, 4, 5, 6, 0, 5, 1, 6}};
  // Shift it so the two meshes are distinguishable in ParaView.
  for (std::size_t i = 0; i < mesh.coordinates.size(); i += 3) mesh.coordinates[i] += 2.0;
  return mesh;
}

// Values that use all 53 bits, different for every entry, field and step.
std::vector<double> sample_values(std::size_t count, double seed) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = std::sin(0.37 * static_cast<double>(i) + seed) * 1e3 + 1.0 / 3.0;
  return values;
}

// ---- reading HDF5 back

// The string attributes of the file's root group.
std::map<std::string, std::string> root_string_attributes(const std::string& file) {
  std::map<std::string, std::string> attributes;
  const hid_t file_id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file_id, 0) << file;
  if (file_id < 0) return attributes;
  const hid_t root = H5Gopen2(file_id, "/", H5P_DEFAULT);
  const auto read_one = [](hid_t location, const char* name, const H5A_info_t*, void* client) -> herr_t {
    const hid_t attribute = H5Aopen(location, name, H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute);
    EXPECT_EQ(H5Tget_class(type), H5T_STRING) << name;
    std::string value(H5Tget_size(type), '\0');
    H5Aread(attribute, type, value.data());
    (*static_cast<std::map<std::string, std::string>*>(client))[name] = value.c_str();  // up to the null
    H5Tclose(type);
    H5Aclose(attribute);
    return 0;
  };
  EXPECT_GE(H5Aiterate2(root, H5_INDEX_NAME, H5_ITER_INC, nullptr, read_one, &attributes), 0) << file;
  H5Gclose(root);
  H5Fclose(file_id);
  return attributes;
}

void expect_dataset_equals(const std::string& file, const std::string& dataset_path,
                           const std::vector<hsize_t>& dimensions, const double* expected) {
  const Dataset dataset = read_dataset(file, dataset_path, false);
  ASSERT_EQ(dataset.dimensions, dimensions) << file << ":" << dataset_path;
  EXPECT_EQ(dataset.type_class, H5T_FLOAT);
  EXPECT_EQ(dataset.type_size, 8u);
  for (std::size_t i = 0; i < dataset.doubles.size(); ++i)
    ASSERT_EQ(dataset.doubles[i], expected[i]) << file << ":" << dataset_path << " entry " << i;
}

// ---- a small XML reader: enough to check that the .xdmf is well formed and to walk it

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<XmlElement> children;

  std::string attribute(const std::string& key) const {
    const auto found = attributes.find(key);
    return found == attributes.end() ? std::string() : found->second;
  }
  std::vector<const XmlElement*> children_named(const std::string& child_name) const {
    std::vector<const XmlElement*> found;
    for (const XmlElement& child : children)
      if (child.name == child_name) found.push_back(&child);
    return found;
  }
  // Every element below this one (depth first) with this name.
  void collect(const std::string& wanted, std::vector<const XmlElement*>& found) const {
    for (const XmlElement& child : children) {
      if (child.name == wanted) found.push_back(&child);
      child.collect(wanted, found);
    }
  }
};

class XmlReader {
 public:
  explicit XmlReader(std::string text) : text_(std::move(text)) {}

  // The root element; throws std::runtime_error at the first thing that is not well formed.
  XmlElement parse() {
    skip_misc();
    XmlElement root = element();
    skip_misc();
    if (position_ != text_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    throw std::runtime_error("XML at offset " + std::to_string(position_) + ": " + reason);
  }
  bool starts_with(const char* prefix) const { return text_.compare(position_, std::strlen(prefix), prefix) == 0; }
  void skip_space() {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_]))) ++position_;
  }
  void skip_past(const char* terminator) {
    const std::size_t end = text_.find(terminator, position_);
    if (end == std::string::npos) fail(std::string("missing ") + terminator);
    position_ = end + std::strlen(terminator);
  }
  // Whitespace, <?...?>, <!-- -->, <!DOCTYPE ... [ ... ]>.
  void skip_misc() {
    for (;;) {
      skip_space();
      if (starts_with("<?")) skip_past("?>");
      else if (starts_with("<!--")) skip_past("-->");
      else if (starts_with("<!DOCTYPE")) {
        const std::size_t bracket = text_.find('[', position_), close = text_.find('>', position_);
        if (bracket != std::string::npos && bracket < close) skip_past("]");
        skip_past(">");
      } else return;
    }
  }
  std::string name() {
    const std::size_t start = position_;
    while (position_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[position_])) ||
                                        std::strchr(":_-.", text_[position_])))
      ++position_;
    if (position_ == start) fail("expected a name");
    return text_.substr(start, position_ - start);
  }
  std::string unescape(const std::string& raw) const {
    static const std::map<std::string, std::string> entities{
        {"amp", "&"}, {"lt", "<"}, {"gt", ">"}, {"quot", "\""}, {"apos", "'"}};
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '<') fail("'<' in text or attribute value");
      if (raw[i] != '&') {
        out += raw[i];
        continue;
      }
      const std::size_t end = raw.find(';', i);
      if (end == std::string::npos) fail("unterminated entity");
      const std::string entity = raw.substr(i + 1, end - i - 1);
      if (!entity.empty() && entity[0] == '#') out += static_cast<char>(std::stoi(entity.substr(1)));
      else if (entities.count(entity)) out += entities.at(entity);
      else fail("unknown entity &" + entity + ";");
      i = end;
    }
    return out;
  }
  XmlElement element() {
    if (!starts_with("<")) fail("expected '<'");
    ++position_;
    XmlElement result;
    result.name = name();
    for (;;) {
      skip_space();
      if (starts_with("/>")) {
        position_ += 2;
        return result;
      }
      if (starts_with(">")) {
        ++position_;
        break;
      }
      const std::string key = name();
      skip_space();
      if (!starts_with("=")) fail("expected '=' after attribute " + key);
      ++position_;
      skip_space();
      if (position_ >= text_.size() || (text_[position_] != '"' && text_[position_] != '\'')) fail("unquoted value");
      const char quote = text_[position_++];
      const std::size_t end = text_.find(quote, position_);
      if (end == std::string::npos) fail("unterminated attribute value");
      if (!result.attributes.emplace(key, unescape(text_.substr(position_, end - position_))).second)
        fail("duplicate attribute " + key);
      position_ = end + 1;
    }
    for (;;) {  // content
      const std::size_t next_tag = text_.find('<', position_);
      if (next_tag == std::string::npos) fail("unclosed element <" + result.name + ">");
      result.text += unescape(text_.substr(position_, next_tag - position_));
      position_ = next_tag;
      if (starts_with("</")) {
        position_ += 2;
        const std::string closing = name();
        if (closing != result.name) fail("</" + closing + "> closes <" + result.name + ">");
        skip_space();
        if (!starts_with(">")) fail("expected '>'");
        ++position_;
        return result;
      }
      if (starts_with("<!--")) skip_past("-->");
      else result.children.push_back(element());
    }
  }

  std::string text_;
  std::size_t position_ = 0;
};

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// Checks every <DataItem Format="HDF"> below `root`: it names an existing file in
// `directory` and a dataset in it whose dimensions and number type are the stated ones.
// Returns the set of files referenced.
std::set<std::string> check_hdf5_references(const XmlElement& root, const fs::path& directory) {
  std::vector<const XmlElement*> items;
  root.collect("DataItem", items);
  std::set<std::string> files;
  for (const XmlElement* item : items) {
    EXPECT_EQ(item->attribute("Format"), "HDF");
    const std::string reference = trimmed(item->text);
    const std::size_t colon = reference.find(":/");
    EXPECT_NE(colon, std::string::npos) << reference;
    if (colon == std::string::npos) continue;
    const std::string file = reference.substr(0, colon), dataset_path = reference.substr(colon + 1);
    files.insert(file);
    EXPECT_TRUE(fs::is_regular_file(directory / file)) << reference;
    if (!fs::is_regular_file(directory / file)) continue;
    const bool is_integer = item->attribute("NumberType") == "Int";
    const Dataset dataset = read_dataset((directory / file).string(), dataset_path, is_integer);
    std::ostringstream dimensions;
    for (std::size_t d = 0; d < dataset.dimensions.size(); ++d) dimensions << (d ? " " : "") << dataset.dimensions[d];
    EXPECT_EQ(item->attribute("Dimensions"), dimensions.str()) << reference;
    EXPECT_EQ(dataset.type_class, is_integer ? H5T_INTEGER : H5T_FLOAT) << reference;
    EXPECT_EQ(std::to_string(dataset.type_size), item->attribute("Precision")) << reference;
  }
  return files;
}

XmlElement parse_xdmf(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return XmlReader(text.str()).parse();
}

// The temporal collection of an .xdmf document.
const XmlElement& temporal_collection(const XmlElement& xdmf) {
  const auto domains = xdmf.children_named("Domain");
  EXPECT_EQ(domains.size(), 1u);
  const auto grids = domains.at(0)->children_named("Grid");
  EXPECT_EQ(grids.size(), 1u);
  EXPECT_EQ(grids.at(0)->attribute("GridType"), "Collection");
  EXPECT_EQ(grids.at(0)->attribute("CollectionType"), "Temporal");
  return *grids.at(0);
}

// The blocks ParaView's XDMF readers make of a multi-mesh .xdmf, by time (the text of the
// Time values): the block names a user sees in the Multiblock Inspector and selects with
// Extract Block, in order. The readers (ParaView 5.11, measured) name a block after its
// grid, and number a grid name used before in the same document ("fluid", "fluid[1]",
// "fluid[2]", ...); a temporal collection inside a spatial collection is one block, named
// by the "XDMF Reader" after the collection. Covers the two layouts a writer can choose:
// a temporal collection of per-step spatial collections, and a spatial collection of
// per-mesh temporal collections.
std::map<std::string, std::vector<std::string>> block_names_by_time(const XmlElement& xdmf) {
  std::map<std::string, std::vector<std::string>> names;
  std::map<std::string, int> uses;
  const auto numbered = [&](const std::string& name) {
    const int earlier = uses[name]++;
    return earlier == 0 ? name : name + "[" + std::to_string(earlier) + "]";
  };
  const auto time_of = [](const XmlElement& grid) {
    const auto times = grid.children_named("Time");
    return times.empty() ? std::string("(no time)") : times[0]->attribute("Value");
  };
  const auto domains = xdmf.children_named("Domain");
  if (domains.size() != 1 || domains[0]->children_named("Grid").size() != 1) {
    ADD_FAILURE() << "expected one Domain with one Grid";
    return names;
  }
  const XmlElement& top = *domains[0]->children_named("Grid")[0];
  if (top.attribute("CollectionType") == "Temporal") {
    for (const XmlElement* step : top.children_named("Grid"))
      for (const XmlElement* grid : step->children_named("Grid"))
        names[time_of(*step)].push_back(numbered(grid->attribute("Name")));
  } else if (top.attribute("CollectionType") == "Spatial") {
    for (const XmlElement* mesh : top.children_named("Grid")) {
      if (mesh->attribute("CollectionType") != "Temporal") {
        ADD_FAILURE() << "grid \"" << mesh->attribute("Name") << "\" of the spatial collection is not a time series";
        continue;
      }
      for (const XmlElement* grid : mesh->children_named("Grid")) names[time_of(*grid)].push_back(mesh->attribute("Name"));
    }
  } else {
    ADD_FAILURE() << "the Domain's grid is not a collection";
  }
  return names;
}

bool no_temporary_files(const std::set<std::string>& names) {
  for (const std::string& name : names)
    if (name.size() >= 4 && name.compare(name.size() - 4, 4, ".tmp") == 0) return false;
  return true;
}

// The fields of one test step, kept alive while the writer reads them.
struct StepFields {
  std::vector<double> fluid_velocity, fluid_pressure, fluid_cell_volume, cell_velocity, cell_coordinates;
  StepFields(int step, const MeshDescription& fluid, const MeshDescription& cells) {
    const std::size_t fluid_nodes = fluid.coordinates.size() / 3, fluid_cells = fluid.connectivity.size() / 8;
    fluid_velocity = sample_values(3 * fluid_nodes, 1.0 * step);
    fluid_pressure = sample_values(fluid_nodes, 2.0 * step + 0.5);
    fluid_cell_volume = sample_values(fluid_cells, 3.0 * step + 0.25);
    cell_velocity = sample_values(cells.coordinates.size(), 4.0 * step);
    cell_coordinates = cells.coordinates;
    for (double& x : cell_coordinates) x += 1e-3 * step + 1e-17;
  }
};

}  // namespace

// ---------------------------------------------------------------- provenance

TEST(IoProvenance, HoldsBuildFactsAndCallerExtras) {
  const Provenance provenance = build_provenance({{"threads", "4"}, {"case", "shear"}, {"host_name", "override"}});
  for (const char* key : {"rouleau_version", "git_hash", "kokkos_version", "kokkoskernels_version", "hdf5_version",
                          "created_utc", "host_name", "threads", "case"})
    EXPECT_NE(provenance.find(key), nullptr) << key;
  EXPECT_EQ(*provenance.find("git_hash"), ROULEAU_GIT_HASH);
  EXPECT_EQ(*provenance.find("rouleau_version"), ROULEAU_VERSION);
  EXPECT_EQ(*provenance.find("kokkos_version"), ROULEAU_KOKKOS_VERSION);
  EXPECT_EQ(*provenance.find("hdf5_version"), std::to_string(H5_VERS_MAJOR) + "." + std::to_string(H5_VERS_MINOR) +
                                                  "." + std::to_string(H5_VERS_RELEASE));
  EXPECT_TRUE(std::regex_match(*provenance.find("created_utc"),
                               std::regex(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}Z)")))
      << *provenance.find("created_utc");
  EXPECT_EQ(*provenance.find("host_name"), "override");  // an extra replaces the built-in entry
  std::set<std::string> keys;
  for (const auto& entry : provenance.attributes) EXPECT_TRUE(keys.insert(entry.first).second) << entry.first;
}

TEST(IoProvenance, MeshHashIsStableAndSeesEveryBit) {
  const MeshDescription mesh = tet_mesh_cube();
  const auto hash_of = [](const MeshDescription& m) {
    return hash_mesh(m.coordinates.data(), m.coordinates.size(), m.connectivity.data(), m.connectivity.size());
  };
  const std::string digest = hash_of(mesh);
  EXPECT_TRUE(std::regex_match(digest, std::regex("[0-9a-f]{16}"))) << digest;
  // The stored digest of this mesh: it changes only if the hash definition changes, which
  // would make the mesh hashes in old output files incomparable.
  EXPECT_EQ(digest, "bb205987c128db35");
  // FNV-1a 64 of no data, with both lengths 0, is fixed too.
  EXPECT_EQ(hash_mesh(nullptr, 0, nullptr, 0), hash_mesh(nullptr, 0, nullptr, 0));

  MeshDescription one_ulp = mesh;
  one_ulp.coordinates[5] = std::nextafter(one_ulp.coordinates[5], 2.0);
  EXPECT_NE(hash_of(one_ulp), digest);
  MeshDescription swapped = mesh;
  std::swap(swapped.connectivity[0], swapped.connectivity[1]);
  EXPECT_NE(hash_of(swapped), digest);
  // Moving a value from one array to the other changes the lengths, hence the digest.
  const double zero = 0.0;
  const long long zero_index = 0;
  EXPECT_NE(hash_mesh(&zero, 1, nullptr, 0), hash_mesh(nullptr, 0, &zero_index, 1));
}

// ---------------------------------------------------------------- XDMF + HDF5

TEST_F(IoTest, HexAndTetSeriesReadsBackExactlyAndXdmfReferencesResolve) {
  const MeshDescription fluid = hex_mesh_2x2x2(), cells = tet_mesh_cube();
  ASSERT_EQ(fluid.coordinates.size(), 27u * 3);
  ASSERT_EQ(fluid.connectivity.size(), 8u * 8);
  const Provenance provenance = build_provenance({{"case", "test <io> & \"quotes\""}, {"threads", "2"}});
  XdmfTimeSeries series(directory_.string(), "run", {fluid, cells}, provenance);
  EXPECT_EQ(series.xdmf_path(), path("run.xdmf"));
  {  // before any step: the two bare meshes side by side
    const XmlElement xdmf = parse_xdmf(series.xdmf_path());
    const auto grids = xdmf.children_named("Domain").at(0)->children_named("Grid");
    ASSERT_EQ(grids.size(), 1u);
    EXPECT_EQ(grids[0]->attribute("CollectionType"), "Spatial");
    EXPECT_EQ(grids[0]->children_named("Grid").size(), 2u);
    EXPECT_EQ(check_hdf5_references(xdmf, directory_), std::set<std::string>{"run_mesh.h5"});
    for (const char* name : {"run_fluid.xdmf", "run_cells.xdmf"}) {  // and each alone
      const XmlElement single = parse_xdmf(path(name));
      const auto bare = single.children_named("Domain").at(0)->children_named("Grid");
      ASSERT_EQ(bare.size(), 1u) << name;
      EXPECT_EQ(bare[0]->attribute("GridType"), "Uniform") << name;
      EXPECT_TRUE(bare[0]->children_named("Time").empty()) << name;
      EXPECT_EQ(check_hdf5_references(single, directory_), std::set<std::string>{"run_mesh.h5"}) << name;
    }
  }

  const std::vector<double> times{0.0, 0.1, 1.0 / 3.0};
  std::vector<std::unique_ptr<StepFields>> written;
  for (int step = 1; step <= 3; ++step) {
    written.push_back(std::make_unique<StepFields>(step, fluid, cells));
    const StepFields& f = *written.back();
    series.write_step(step, times[step - 1],
                      {{{"velocity", 3, f.fluid_velocity.data()}, {"pressure", 1, f.fluid_pressure.data()}},
                       {{"velocity", 3, f.cell_velocity.data()}}},
                      {{{"volume", 1, f.fluid_cell_volume.data()}}, {}},
                      {nullptr, f.cell_coordinates.data()});
  }
  EXPECT_EQ(series.step_count(), 3u);
  EXPECT_EQ(files(), (std::set<std::string>{"run.xdmf", "run_fluid.xdmf", "run_cells.xdmf", "run_mesh.h5",
                                            "run_000001.h5", "run_000002.h5", "run_000003.h5"}));
  EXPECT_EQ(series.mesh_xdmf_path("cells"), path("run_cells.xdmf"));

  // Static mesh file.
  const std::string mesh_file = series.mesh_path();
  expect_dataset_equals(mesh_file, "/fluid/coordinates", {27, 3}, fluid.coordinates.data());
  expect_dataset_equals(mesh_file, "/cells/coordinates", {8, 3}, cells.coordinates.data());
  for (const MeshDescription* mesh : {&fluid, &cells}) {
    const Dataset connectivity = read_dataset(mesh_file, "/" + mesh->name + "/connectivity", true);
    const hsize_t per_cell = static_cast<hsize_t>(nodes_per_cell(mesh->cell_type));
    EXPECT_EQ(connectivity.dimensions, (std::vector<hsize_t>{mesh->connectivity.size() / per_cell, per_cell}));
    EXPECT_EQ(connectivity.type_class, H5T_INTEGER);
    EXPECT_EQ(connectivity.type_size, 8u);
    EXPECT_EQ(connectivity.integers, mesh->connectivity);
  }

  // Step files.
  for (int step = 1; step <= 3; ++step) {
    const StepFields& f = *written[static_cast<std::size_t>(step - 1)];
    const std::string file = series.step_path(step);
    expect_dataset_equals(file, "/time", {1}, &times[static_cast<std::size_t>(step - 1)]);
    EXPECT_EQ(read_dataset(file, "/step", true).integers, std::vector<long long>{step});
    expect_dataset_equals(file, "/fluid/velocity", {27, 3}, f.fluid_velocity.data());
    expect_dataset_equals(file, "/fluid/pressure", {27}, f.fluid_pressure.data());
    expect_dataset_equals(file, "/fluid/volume", {8}, f.fluid_cell_volume.data());
    expect_dataset_equals(file, "/cells/velocity", {8, 3}, f.cell_velocity.data());
    expect_dataset_equals(file, "/cells/coordinates", {8, 3}, f.cell_coordinates.data());
  }

  // Provenance on every .h5 root, with the mesh hashes added by the writer.
  for (const std::string& name : files()) {
    if (fs::path(name).extension() != ".h5") continue;
    const auto attributes = root_string_attributes(path(name));
    for (const auto& [key, value] : provenance.attributes) {
      ASSERT_TRUE(attributes.count(key)) << name << " lacks " << key;
      EXPECT_EQ(attributes.at(key), value) << name << " " << key;
    }
    EXPECT_EQ(attributes.at("git_hash"), ROULEAU_GIT_HASH);
    EXPECT_EQ(attributes.at("mesh_hash_fluid"), hash_mesh(fluid.coordinates.data(), fluid.coordinates.size(),
                                                          fluid.connectivity.data(), fluid.connectivity.size()));
    EXPECT_TRUE(attributes.count("mesh_hash_cells")) << name;
  }

  // The .xdmf: well formed, every reference resolves, the structure ParaView expects.
  const XmlElement xdmf = parse_xdmf(series.xdmf_path());
  EXPECT_EQ(xdmf.name, "Xdmf");
  EXPECT_EQ(xdmf.attribute("Version"), "3.0");
  EXPECT_EQ(check_hdf5_references(xdmf, directory_),
            (std::set<std::string>{"run_mesh.h5", "run_000001.h5", "run_000002.h5", "run_000003.h5"}));
  std::map<std::string, std::string> information;
  for (const XmlElement* item : xdmf.children_named("Domain").at(0)->children_named("Information"))
    information[item->attribute("Name")] = item->attribute("Value");
  EXPECT_EQ(information.at("case"), "test <io> & \"quotes\"");  // escaped and read back
  EXPECT_EQ(information.at("git_hash"), ROULEAU_GIT_HASH);

  // A spatial collection of one temporal collection per mesh, each with a uniform grid per
  // step (why this layout: EveryStepOfATwoMeshSeriesShowsTheSameBlocks).
  const auto tops = xdmf.children_named("Domain").at(0)->children_named("Grid");
  ASSERT_EQ(tops.size(), 1u);
  EXPECT_EQ(tops[0]->attribute("GridType"), "Collection");
  EXPECT_EQ(tops[0]->attribute("CollectionType"), "Spatial");
  const auto mesh_series = tops[0]->children_named("Grid");
  ASSERT_EQ(mesh_series.size(), 2u);
  for (std::size_t m = 0; m < mesh_series.size(); ++m) {
    EXPECT_EQ(mesh_series[m]->attribute("Name"), m == 0 ? "fluid" : "cells");
    EXPECT_EQ(mesh_series[m]->attribute("CollectionType"), "Temporal");
    ASSERT_EQ(mesh_series[m]->children_named("Grid").size(), 3u);
  }
  for (std::size_t s = 0; s < 3; ++s) {
    const std::vector<const XmlElement*> grids{mesh_series[0]->children_named("Grid")[s],
                                               mesh_series[1]->children_named("Grid")[s]};
    for (std::size_t m = 0; m < grids.size(); ++m) {
      EXPECT_EQ(grids[m]->attribute("GridType"), "Uniform");
      EXPECT_EQ(grids[m]->attribute("Name"), m == 0 ? "fluid" : "cells");
      ASSERT_EQ(grids[m]->children_named("Time").size(), 1u);
      EXPECT_EQ(std::strtod(grids[m]->children_named("Time")[0]->attribute("Value").c_str(), nullptr), times[s]);
    }
    EXPECT_EQ(grids[0]->children_named("Topology").at(0)->attribute("TopologyType"), "Hexahedron");
    EXPECT_EQ(grids[0]->children_named("Topology").at(0)->attribute("NumberOfElements"), "8");
    EXPECT_EQ(grids[1]->children_named("Topology").at(0)->attribute("TopologyType"), "Tetrahedron");
    EXPECT_EQ(grids[1]->children_named("Topology").at(0)->attribute("NumberOfElements"), "6");
    // The fluid stays in the mesh file; the moving cells' geometry comes from the step file.
    EXPECT_EQ(trimmed(grids[0]->children_named("Geometry").at(0)->children.at(0).text),
              "run_mesh.h5:/fluid/coordinates");
    EXPECT_EQ(trimmed(grids[1]->children_named("Geometry").at(0)->children.at(0).text),
              "run_00000" + std::to_string(s + 1) + ".h5:/cells/coordinates");
    std::map<std::string, std::string> fluid_attributes;  // name -> "type center"
    for (const XmlElement* attribute : grids[0]->children_named("Attribute"))
      fluid_attributes[attribute->attribute("Name")] =
          attribute->attribute("AttributeType") + " " + attribute->attribute("Center");
    EXPECT_EQ(fluid_attributes, (std::map<std::string, std::string>{
                                    {"velocity", "Vector Node"}, {"pressure", "Scalar Node"}, {"volume", "Scalar Cell"}}));
  }
  // Each mesh's own .xdmf holds the same grids, with the same provenance.
  for (std::size_t m = 0; m < mesh_series.size(); ++m) {
    const std::string name = mesh_series[m]->attribute("Name");
    const XmlElement single = parse_xdmf(path("run_" + name + ".xdmf"));
    const XmlElement& temporal = temporal_collection(single);
    EXPECT_EQ(temporal.attribute("Name"), name);
    const auto grids = temporal.children_named("Grid");
    ASSERT_EQ(grids.size(), 3u);
    for (std::size_t s = 0; s < grids.size(); ++s) {
      const XmlElement& in_all = *mesh_series[m]->children_named("Grid")[s];
      EXPECT_EQ(grids[s]->attribute("Name"), name);
      EXPECT_EQ(grids[s]->children_named("Time").at(0)->attribute("Value"),
                in_all.children_named("Time").at(0)->attribute("Value"));
      std::vector<const XmlElement*> items, items_in_all;
      grids[s]->collect("DataItem", items);
      in_all.collect("DataItem", items_in_all);
      ASSERT_EQ(items.size(), items_in_all.size());
      for (std::size_t i = 0; i < items.size(); ++i) EXPECT_EQ(trimmed(items[i]->text), trimmed(items_in_all[i]->text));
    }
    std::map<std::string, std::string> single_information;
    for (const XmlElement* item : single.children_named("Domain").at(0)->children_named("Information"))
      single_information[item->attribute("Name")] = item->attribute("Value");
    EXPECT_EQ(single_information, information) << name;
  }
  EXPECT_TRUE(no_temporary_files(files()));
}

TEST_F(IoTest, EveryStepOfATwoMeshSeriesShowsTheSameBlocks) {
  // ParaView must show the fluid and the cells as the same two blocks at every step, so that
  // a block extracted at t = 0 keeps its mesh while the series plays. Per-step spatial
  // collections of "fluid" and "cells" (this writer's former layout) came out of ParaView 5.11
  // as fluid, fluid[1], fluid[2], ...: a block extracted at t = 0 was empty at later times.
  const XmlElement former = XmlReader(
      "<Xdmf><Domain><Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">"
      "<Grid Name=\"step_0\" GridType=\"Collection\" CollectionType=\"Spatial\"><Time Value=\"0\"/>"
      "<Grid Name=\"fluid\" GridType=\"Uniform\"/><Grid Name=\"cells\" GridType=\"Uniform\"/></Grid>"
      "<Grid Name=\"step_5\" GridType=\"Collection\" CollectionType=\"Spatial\"><Time Value=\"0.5\"/>"
      "<Grid Name=\"fluid\" GridType=\"Uniform\"/><Grid Name=\"cells\" GridType=\"Uniform\"/></Grid>"
      "</Grid></Domain></Xdmf>").parse();
  EXPECT_EQ(block_names_by_time(former), (std::map<std::string, std::vector<std::string>>{
                                             {"0", {"fluid", "cells"}}, {"0.5", {"fluid[1]", "cells[1]"}}}));

  const MeshDescription fluid = hex_mesh_2x2x2(), cells = tet_mesh_cube();
  const Provenance provenance = build_provenance({{"case", "two meshes"}});
  std::vector<double> times;
  std::set<std::string> step_files{"run_mesh.h5"};
  {
    XdmfTimeSeries series(directory_.string(), "run", {fluid, cells}, provenance);
    for (int step : {0, 5, 10, 15}) {
      const StepFields f(step, fluid, cells);
      times.push_back(1e-4 * step);
      series.write_step(step, times.back(),
                        {{{"velocity", 3, f.fluid_velocity.data()}, {"pressure", 1, f.fluid_pressure.data()}},
                         {{"velocity", 3, f.cell_velocity.data()}}},
                        {}, {nullptr, f.cell_coordinates.data()});
      step_files.insert(fs::path(series.step_path(step)).filename().string());
    }
  }
  // The same blocks, in the same order, under the same names, at every step written.
  const auto expect_blocks_at_every_step = [&](std::size_t step_count) {
    const auto names = block_names_by_time(parse_xdmf(path("run.xdmf")));
    std::vector<double> listed;
    for (const auto& [time, blocks] : names) {
      listed.push_back(std::strtod(time.c_str(), nullptr));
      EXPECT_EQ(blocks, (std::vector<std::string>{"fluid", "cells"})) << "at t = " << time;
    }
    EXPECT_EQ(listed, std::vector<double>(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(step_count)));
  };
  expect_blocks_at_every_step(4);

  // One .xdmf per mesh, each a temporal collection of that mesh alone (one uniform grid per
  // step, nothing nested): every reader opens it as one dataset that plays.
  const auto expect_mesh_files = [&](std::size_t step_count, const std::set<std::string>& files_listed) {
    for (const MeshDescription* mesh : {&fluid, &cells}) {
      const std::string name = "run_" + mesh->name + ".xdmf";
      const XmlElement single = parse_xdmf(path(name));
      const XmlElement& temporal = temporal_collection(single);
      EXPECT_EQ(temporal.attribute("Name"), mesh->name) << name;
      const auto grids = temporal.children_named("Grid");
      ASSERT_EQ(grids.size(), step_count) << name;
      for (std::size_t s = 0; s < grids.size(); ++s) {
        EXPECT_EQ(grids[s]->attribute("GridType"), "Uniform") << name;
        EXPECT_EQ(grids[s]->attribute("Name"), mesh->name) << name;
        ASSERT_EQ(grids[s]->children_named("Time").size(), 1u) << name;
        EXPECT_EQ(std::strtod(grids[s]->children_named("Time")[0]->attribute("Value").c_str(), nullptr), times[s]);
      }
      EXPECT_EQ(check_hdf5_references(single, directory_), files_listed) << name;
    }
  };
  expect_mesh_files(4, step_files);

  // A run restarted from step 10 lists steps 0 to 10 in every .xdmf, in the same layout.
  XdmfTimeSeries resumed(directory_.string(), "run", {fluid, cells}, provenance);
  resumed.adopt_written_steps(10);
  step_files.erase("run_000015.h5");
  EXPECT_FALSE(fs::exists(path("run_000015.h5")));
  expect_blocks_at_every_step(3);
  expect_mesh_files(3, step_files);
  EXPECT_EQ(check_hdf5_references(parse_xdmf(path("run.xdmf")), directory_), step_files);
  EXPECT_TRUE(no_temporary_files(files()));
}

TEST_F(IoTest, SingleMeshSeriesIsAUniformGridPerStep) {
  const MeshDescription fluid = hex_mesh_2x2x2();
  XdmfTimeSeries series(directory_.string(), "fluid_only", {fluid}, build_provenance());
  // Before any step: the bare mesh, without time or fields (ParaView crashes on an empty
  // temporal collection).
  {
    const XmlElement xdmf = parse_xdmf(series.xdmf_path());
    const auto grids = xdmf.children_named("Domain").at(0)->children_named("Grid");
    ASSERT_EQ(grids.size(), 1u);
    EXPECT_EQ(grids[0]->attribute("GridType"), "Uniform");
    EXPECT_TRUE(grids[0]->children_named("Time").empty());
    EXPECT_TRUE(grids[0]->children_named("Attribute").empty());
    EXPECT_EQ(check_hdf5_references(xdmf, directory_), std::set<std::string>{"fluid_only_mesh.h5"});
  }
  const std::vector<double> pressure = sample_values(27, 0.0);
  for (int step : {0, 10})
    series.write_step(step, 0.5 * step, {{{"pressure", 1, pressure.data()}}}, {});
  const XmlElement xdmf = parse_xdmf(series.xdmf_path());
  const auto grids = temporal_collection(xdmf).children_named("Grid");
  ASSERT_EQ(grids.size(), 2u);
  EXPECT_EQ(grids[1]->attribute("GridType"), "Uniform");
  EXPECT_EQ(grids[1]->children_named("Time").at(0)->attribute("Value"), "5");
  EXPECT_EQ(check_hdf5_references(xdmf, directory_),
            (std::set<std::string>{"fluid_only_mesh.h5", "fluid_only_000000.h5", "fluid_only_000010.h5"}));
  EXPECT_TRUE(no_temporary_files(files()));
}

TEST_F(IoTest, FailedStepLeavesCompleteFilesAndAnXdmfOfEarlierSteps) {
  const MeshDescription fluid = hex_mesh_2x2x2();
  XdmfTimeSeries series(directory_.string(), "run", {fluid}, build_provenance());
  const std::vector<double> pressure = sample_values(27, 1.0);
  const auto write = [&](int step) { series.write_step(step, step * 0.1, {{{"pressure", 1, pressure.data()}}}, {}); };
  write(1);
  write(2);
  const std::string xdmf_before = read_text("run.xdmf");

  // A writer that cannot create its temporary file (here: a folder sits on PATH.tmp) throws an
  // error naming the file, and the .xdmf still lists exactly the complete steps.
  fs::create_directory(path("run_000003.h5.tmp"));
  try {
    write(3);
    FAIL() << "write_step should have thrown";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("run_000003.h5.tmp"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(path("run_000003.h5")));
  EXPECT_EQ(read_text("run.xdmf"), xdmf_before);
  EXPECT_EQ(check_hdf5_references(parse_xdmf(series.xdmf_path()), directory_),
            (std::set<std::string>{"run_mesh.h5", "run_000001.h5", "run_000002.h5"}));

  // A half-written file left by a crashed writer is never referenced, and the next write
  // of that step replaces it.
  fs::remove(path("run_000003.h5.tmp"));
  std::ofstream(path("run_000003.h5.tmp")) << "half an HDF5 file";
  EXPECT_EQ(check_hdf5_references(parse_xdmf(series.xdmf_path()), directory_).count("run_000003.h5"), 0u);
  write(3);
  EXPECT_EQ(check_hdf5_references(parse_xdmf(series.xdmf_path()), directory_).count("run_000003.h5"), 1u);
  expect_dataset_equals(series.step_path(3), "/fluid/pressure", {27}, pressure.data());
  EXPECT_TRUE(no_temporary_files(files()));
}

TEST_F(IoTest, RejectsInconsistentInputBeforeWriting) {
  const MeshDescription fluid = hex_mesh_2x2x2();
  MeshDescription out_of_range = fluid;
  out_of_range.connectivity[3] = 27;
  EXPECT_THROW(XdmfTimeSeries(directory_.string(), "run", {out_of_range}, {}), std::invalid_argument);
  MeshDescription ragged = fluid;
  ragged.connectivity.pop_back();
  EXPECT_THROW(XdmfTimeSeries(directory_.string(), "run", {ragged}, {}), std::invalid_argument);
  EXPECT_THROW(XdmfTimeSeries(directory_.string(), "run/../x", {fluid}, {}), std::invalid_argument);
  EXPECT_THROW(XdmfTimeSeries(directory_.string(), "run", {fluid, fluid}, {}), std::invalid_argument);

  XdmfTimeSeries series(directory_.string(), "run", {fluid}, {});
  const std::vector<double> values = sample_values(3 * 27, 0.0);
  EXPECT_THROW(series.write_step(1, 0.0, {{{"velocity", 2, values.data()}}}, {}), std::invalid_argument);
  EXPECT_THROW(series.write_step(1, 0.0, {{{"p", 1, values.data()}, {"p", 1, values.data()}}}, {}),
               std::invalid_argument);
  EXPECT_THROW(series.write_step(1, 0.0, {{{"coordinates", 3, values.data()}}}, {}), std::invalid_argument);
  EXPECT_THROW(series.write_step(1, 0.0, {{}, {}}, {}), std::invalid_argument);  // two entries, one mesh
  EXPECT_THROW(series.write_step(1, 0.0, {{{"p", 1, nullptr}}}, {}), std::invalid_argument);
  EXPECT_EQ(series.step_count(), 0u);
  series.write_step(5, 0.0, {{{"p", 1, values.data()}}}, {});
  EXPECT_THROW(series.write_step(5, 1.0, {{{"p", 1, values.data()}}}, {}), std::invalid_argument);
  EXPECT_THROW(series.write_step(4, 1.0, {{{"p", 1, values.data()}}}, {}), std::invalid_argument);
  EXPECT_EQ(files(), (std::set<std::string>{"run.xdmf", "run_fluid.xdmf", "run_mesh.h5", "run_000005.h5"}));
}

// ---------------------------------------------------------------- diagnostics CSV

namespace {
// The CSV as (header, rows of numbers).
std::pair<std::vector<std::string>, std::vector<std::vector<double>>> read_csv(const std::string& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  bool first = true;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cells_of_line(line);
    for (std::string cell; std::getline(cells_of_line, cell, ',');) cells.push_back(cell);
    if (first) {
      header = cells;
      first = false;
      continue;
    }
    std::vector<double> row;
    for (const std::string& cell : cells) {
      char* end = nullptr;
      row.push_back(std::strtod(cell.c_str(), &end));
      EXPECT_EQ(*end, '\0') << "not a number: " << cell;
    }
    rows.push_back(row);
  }
  return {header, rows};
}
// ---- checkpoints

CheckpointData sample_checkpoint(long long step) {
  CheckpointData data;
  data.step = step;
  data.time = 0.25 * step;
  data.wall_seconds = 12.5;
  data.resolved_case = "[case]\nname = \"x\"\n";
  data.labels["fluid_mesh_hash"] = "0123456789abcdef";
  data.reals["fluid/state"] = {1.0, -2.5, 1e-300, std::numeric_limits<double>::denorm_min()};
  data.reals["cells/positions"] = {};
  data.integers["fluid/steps"] = {step};
  return data;
}

TEST_F(IoTest, CheckpointRoundTripsEveryEntryBitForBit) {
  fs::create_directories(path(""));
  const CheckpointData written = sample_checkpoint(7);
  write_checkpoint_file(path("c.h5"), written, build_provenance());
  const CheckpointData read = read_checkpoint_file(path("c.h5"));
  EXPECT_EQ(read.step, 7);
  EXPECT_EQ(read.time, written.time);
  EXPECT_EQ(read.wall_seconds, written.wall_seconds);
  EXPECT_EQ(read.resolved_case, written.resolved_case);
  EXPECT_EQ(read.labels, written.labels);
  EXPECT_EQ(read.reals, written.reals);
  EXPECT_EQ(read.integers, written.integers);
  EXPECT_EQ(files(), std::set<std::string>{"c.h5"});  // no .tmp left
  EXPECT_THROW(read.real("fluid/state", 5), std::runtime_error);
  EXPECT_THROW(read.real("fluid/missing"), std::runtime_error);
}

TEST_F(IoTest, CheckpointWithAChangedValueIsRefusedByItsChecksum) {
  fs::create_directories(path(""));
  write_checkpoint_file(path("c.h5"), sample_checkpoint(3), build_provenance());
  {  // one state value changed in place, as a damaged disk block would
    const hid_t file = H5Fopen(path("c.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    const hid_t dataset = H5Dopen2(file, "/reals/fluid/state", H5P_DEFAULT);
    ASSERT_GE(dataset, 0);
    const double changed[4] = {1.0, -2.5000000000000004, 1e-300, std::numeric_limits<double>::denorm_min()};
    ASSERT_GE(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, changed), 0);
    H5Dclose(dataset);
    H5Fclose(file);
  }
  try {
    read_checkpoint_file(path("c.h5"));
    FAIL() << "a changed checkpoint was accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("checksum"), std::string::npos) << error.what();
  }
}

TEST_F(IoTest, CheckpointStoreKeepsTheNewestAndDropsAnAbandonedFuture) {
  CheckpointStore store(path("run"), 2);
  for (long long step : {0, 10, 20, 30}) store.write(sample_checkpoint(step), build_provenance());
  auto listed = store.list();
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0].first, 30);
  EXPECT_EQ(listed[1].first, 20);
  EXPECT_EQ(store.last_path(), store.path_of(30));
  // A run restarted from step 20 writes step 25: step 30 belonged to the abandoned branch.
  store.write(sample_checkpoint(25), build_provenance());
  listed = store.list();
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0].first, 25);
  EXPECT_EQ(listed[1].first, 20);
  EXPECT_EQ(newest_valid_checkpoint(path("run")).data.step, 25);
  // A .tmp (a write cut off) is never taken for a checkpoint.
  std::ofstream(store.path_of(99) + ".tmp") << "half";
  EXPECT_EQ(newest_valid_checkpoint(path("run")).data.step, 25);
}

}  // namespace

TEST_F(IoTest, DiagnosticsTableRoundTripsEveryDoubleExactly) {
  const std::string file = path("sub/diagnostics.csv");
  const std::vector<std::string> columns{"step", "time", "kinetic_energy", "cell_volume_error"};
  const std::vector<std::vector<double>> rows{
      {0, 0.0, 0.1, -0.0},
      {1, 1.0 / 3.0, 1e-300, 4.9406564584124654e-324},
      {2, std::numeric_limits<double>::max(), -2.5e17, std::numeric_limits<double>::infinity()},
      {3, 0.30000000000000004, std::nextafter(1.0, 2.0), std::numeric_limits<double>::quiet_NaN()}};
  {
    DiagnosticsTable table(file, columns, {}, 0);
    EXPECT_EQ(read_csv(file).first, columns);  // the header is there from the start
    EXPECT_TRUE(read_csv(file).second.empty());
    for (const auto& row : rows) table.add_row(row);
    EXPECT_THROW(table.add_row({1.0, 2.0}), std::invalid_argument);
    EXPECT_EQ(table.row_count(), rows.size());
    table.flush();
    const auto [header, read_rows] = read_csv(file);
    EXPECT_EQ(header, columns);
    ASSERT_EQ(read_rows.size(), rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (std::size_t c = 0; c < columns.size(); ++c) {
        if (std::isnan(rows[r][c])) {
          EXPECT_TRUE(std::isnan(read_rows[r][c]));
          continue;
        }
        EXPECT_EQ(read_rows[r][c], rows[r][c]) << "row " << r << " column " << columns[c];
        EXPECT_EQ(std::signbit(read_rows[r][c]), std::signbit(rows[r][c]));
      }
    table.add_row({4, 4.0, 4.0, 4.0});  // not flushed: the destructor writes it
    EXPECT_EQ(read_csv(file).second.size(), rows.size());
  }
  EXPECT_EQ(read_csv(file).second.size(), rows.size() + 1);
  EXPECT_FALSE(fs::exists(file + ".tmp"));
}

TEST_F(IoTest, DiagnosticsTableFlushesEveryNRowsAndChecksColumns) {
  const std::string file = path("diagnostics.csv");
  DiagnosticsTable table(file, {"step", "time"}, {}, 2);
  table.add_row({1, 0.1});
  EXPECT_EQ(read_csv(file).second.size(), 0u);
  table.add_row({2, 0.2});
  EXPECT_EQ(read_csv(file).second.size(), 2u);
  table.add_row({3, 0.3});
  EXPECT_EQ(read_csv(file).second.size(), 2u);
  EXPECT_THROW(DiagnosticsTable(path("bad.csv"), {"a", "a"}), std::invalid_argument);
  EXPECT_THROW(DiagnosticsTable(path("bad.csv"), {"a,b"}), std::invalid_argument);
  EXPECT_THROW(DiagnosticsTable(path("bad.csv"), {}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path("bad.csv")));
}

TEST_F(IoTest, DiagnosticsTableStartsOnDiskWithTheRowsItContinues) {
  // A restarted run's table: the rows of the run it continues are in the file from the
  // moment the table exists (a kill before the first new row must not lose them), by
  // column name, NaN where a row lacks a column.
  const std::string file = path("continued.csv");
  const std::vector<std::map<std::string, double>> earlier{{{"step", 1}, {"time", 0.5}, {"dropped", 9}}, {{"step", 2}}};
  DiagnosticsTable table(file, {"step", "time"}, earlier, 0);
  const auto [header, rows] = read_csv(file);
  EXPECT_EQ(header, (std::vector<std::string>{"step", "time"}));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (std::vector<double>{1, 0.5}));
  EXPECT_EQ(rows[1][0], 2.0);
  EXPECT_TRUE(std::isnan(rows[1][1]));
  EXPECT_EQ(table.row_count(), 2u);
}
