#include "io/xdmf_writer.hpp"

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"

namespace rouleau {

int nodes_per_cell(CellType cell_type) {
  switch (cell_type) {
    case CellType::hexahedron8: return 8;
    case CellType::tetrahedron4: return 4;
  }
  throw std::invalid_argument("rouleau::nodes_per_cell: unknown cell type");
}

namespace {

constexpr const char* xdmf_who = "rouleau::XdmfTimeSeries";

// "rouleau::XdmfTimeSeries: " + detail, the start of every error message here.
std::string xdmf_where(const std::string& detail) { return std::string(xdmf_who) + ": " + detail; }

// ---- names and XML

void check_name(const std::string& what, const std::string& name) {
  const bool allowed = !name.empty() && name.find_first_not_of(
                                            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") ==
                                            std::string::npos;
  if (!allowed || name == "." || name == "..")
    throw std::invalid_argument(xdmf_where(what) + " \"" + name +
                                "\": use only letters, digits, '_', '-' and '.'");
}

std::string xml_escaped(const std::string& text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&apos;"; break;
      case '\n': escaped += "&#10;"; break;
      case '\r': escaped += "&#13;"; break;
      case '\t': escaped += "&#9;"; break;
      default: escaped += c;
    }
  }
  return escaped;
}

std::string exact_decimal(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

const char* xdmf_topology_type(CellType cell_type) {
  return cell_type == CellType::hexahedron8 ? "Hexahedron" : "Tetrahedron";
}

// <DataItem> of an HDF5 dataset: "float" (Float, 8 bytes) or "int" (Int, 8 bytes).
std::string data_item(const std::string& indent, std::size_t rows, int columns, bool is_integer,
                      const std::string& file_name, const std::string& dataset_path) {
  std::string dimensions = std::to_string(rows);
  if (columns != 1) dimensions += " " + std::to_string(columns);
  return indent + "<DataItem Dimensions=\"" + dimensions + "\" NumberType=\"" + (is_integer ? "Int" : "Float") +
         "\" Precision=\"8\" Format=\"HDF\">" + file_name + ":" + dataset_path + "</DataItem>\n";
}

}  // namespace

// ---- XdmfTimeSeries

XdmfTimeSeries::XdmfTimeSeries(std::string directory, std::string basename, std::vector<MeshDescription> meshes,
                               Provenance provenance)
    : directory_(std::move(directory)), basename_(std::move(basename)), provenance_(std::move(provenance)) {
  check_name("basename", basename_);
  if (meshes.empty()) throw std::invalid_argument(xdmf_where(basename_ + ": no meshes"));
  std::set<std::string> mesh_names;
  for (const MeshDescription& mesh : meshes) {
    check_name("mesh name", mesh.name);
    if (!mesh_names.insert(mesh.name).second)
      throw std::invalid_argument(xdmf_where("duplicate mesh name \"" + mesh.name + "\""));
    const std::size_t per_cell = static_cast<std::size_t>(nodes_per_cell(mesh.cell_type));
    const std::string mesh_where = xdmf_where("mesh \"" + mesh.name + "\": ");
    if (mesh.coordinates.empty() || mesh.coordinates.size() % 3 != 0)
      throw std::invalid_argument(mesh_where + std::to_string(mesh.coordinates.size()) +
                                  " coordinates: need a positive multiple of 3");
    if (mesh.connectivity.empty() || mesh.connectivity.size() % per_cell != 0)
      throw std::invalid_argument(mesh_where + std::to_string(mesh.connectivity.size()) +
                                  " connectivity entries: need a positive multiple of " + std::to_string(per_cell));
    const std::size_t node_count = mesh.coordinates.size() / 3;
    for (std::size_t i = 0; i < mesh.connectivity.size(); ++i) {
      const long long node = mesh.connectivity[i];
      if (node < 0 || static_cast<unsigned long long>(node) >= node_count)
        throw std::invalid_argument(mesh_where + "cell " + std::to_string(i / per_cell) + " names node " +
                                    std::to_string(node) + " of " + std::to_string(node_count));
    }
    meshes_.push_back({mesh.name, mesh.cell_type, node_count, mesh.connectivity.size() / per_cell});
    provenance_.set("mesh_hash_" + mesh.name, hash_mesh(mesh.coordinates.data(), mesh.coordinates.size(),
                                                        mesh.connectivity.data(), mesh.connectivity.size()));
  }

  std::filesystem::create_directories(directory_);
  write_hdf5_file_atomically(mesh_path(), xdmf_who, provenance_, [&](const Hdf5File& file) {
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      const std::string group = "/" + meshes[m].name;
      write_double_array(file, group + "/coordinates", meshes[m].coordinates.data(), meshes_[m].node_count, 3);
      const hsize_t per_cell = static_cast<hsize_t>(nodes_per_cell(meshes[m].cell_type));
      write_dataset(file, group + "/connectivity", H5T_NATIVE_LLONG, H5T_STD_I64LE, meshes[m].connectivity.data(),
                    {static_cast<hsize_t>(meshes_[m].cell_count), per_cell});
    }
  });
  write_xdmf_files();
}

std::string XdmfTimeSeries::xdmf_path() const { return (std::filesystem::path(directory_) / (basename_ + ".xdmf")).string(); }

std::string XdmfTimeSeries::mesh_xdmf_path(const std::string& mesh_name) const {
  return (std::filesystem::path(directory_) / (basename_ + "_" + mesh_name + ".xdmf")).string();
}

std::string XdmfTimeSeries::mesh_path() const {
  return (std::filesystem::path(directory_) / (basename_ + "_mesh.h5")).string();
}

std::string XdmfTimeSeries::file_name_of_step(int step) const {
  char number[16];
  std::snprintf(number, sizeof number, "%06d", step);
  return basename_ + "_" + number + ".h5";
}

std::string XdmfTimeSeries::step_path(int step) const {
  return (std::filesystem::path(directory_) / file_name_of_step(step)).string();
}

void XdmfTimeSeries::write_step(int step, double time, const std::vector<std::vector<FieldView>>& nodal_fields_per_mesh,
                                const std::vector<std::vector<FieldView>>& cell_fields_per_mesh,
                                const std::vector<const double*>& moved_coordinates_per_mesh) {
  const std::string step_where = xdmf_where("write_step " + std::to_string(step) + ": ");
  if (step < 0 || (!steps_.empty() && step <= steps_.back().step))
    throw std::invalid_argument(step_where + "steps must be non-negative and increasing (last written: " +
                                (steps_.empty() ? std::string("none") : std::to_string(steps_.back().step)) + ")");
  const auto check_per_mesh_count = [&](std::size_t count, const char* what) {
    if (count != 0 && count != meshes_.size())
      throw std::invalid_argument(step_where + what + " has " + std::to_string(count) + " entries for " +
                                  std::to_string(meshes_.size()) + " meshes");
  };
  check_per_mesh_count(nodal_fields_per_mesh.size(), "nodal_fields_per_mesh");
  check_per_mesh_count(cell_fields_per_mesh.size(), "cell_fields_per_mesh");
  check_per_mesh_count(moved_coordinates_per_mesh.size(), "moved_coordinates_per_mesh");

  // What goes into the step: (mesh, field, its entity count) in write order, checked first.
  struct PendingField {
    std::size_t mesh;
    const FieldView* field;
    std::size_t entity_count;
  };
  std::vector<PendingField> pending;
  StepRecord record{step, time, {}};
  for (std::size_t m = 0; m < meshes_.size(); ++m) {
    const MeshLayout& mesh = meshes_[m];
    MeshStepRecord mesh_record{!moved_coordinates_per_mesh.empty() && moved_coordinates_per_mesh[m] != nullptr, {}};
    std::set<std::string> field_names;
    const auto add_fields = [&](const std::vector<std::vector<FieldView>>& per_mesh, Center center) {
      if (per_mesh.empty()) return;
      for (const FieldView& field : per_mesh[m]) {
        const std::string field_where = step_where + "mesh \"" + mesh.name + "\" field \"" + field.name + "\": ";
        check_name("field name", field.name);
        if (field.name == "coordinates" || !field_names.insert(field.name).second)
          throw std::invalid_argument(field_where + "name reserved or already used in this mesh");
        if (field.components != 1 && field.components != 3)
          throw std::invalid_argument(field_where + std::to_string(field.components) + " components (need 1 or 3)");
        if (field.data == nullptr) throw std::invalid_argument(field_where + "null data");
        mesh_record.fields.push_back({field.name, center, field.components});
        pending.push_back({m, &field, center == Center::node ? mesh.node_count : mesh.cell_count});
      }
    };
    add_fields(nodal_fields_per_mesh, Center::node);
    add_fields(cell_fields_per_mesh, Center::cell);
    record.meshes.push_back(std::move(mesh_record));
  }

  write_hdf5_file_atomically(step_path(step), xdmf_who, provenance_, [&](const Hdf5File& file) {
    const long long step_number = step;
    write_dataset(file, "/step", H5T_NATIVE_LLONG, H5T_STD_I64LE, &step_number, {1});
    write_double_array(file, "/time", &time, 1, 1);
    for (std::size_t m = 0; m < meshes_.size(); ++m)
      if (record.meshes[m].moved)
        write_double_array(file, "/" + meshes_[m].name + "/coordinates", moved_coordinates_per_mesh[m],
                           meshes_[m].node_count, 3);
    for (const PendingField& item : pending)
      write_double_array(file, "/" + meshes_[item.mesh].name + "/" + item.field->name, item.field->data,
                         item.entity_count, item.field->components);
  });
  steps_.push_back(std::move(record));
  write_xdmf_files();
}

void XdmfTimeSeries::adopt_written_steps(int last_step) {
  const std::regex pattern(std::regex_replace(basename_, std::regex("[.]"), "\\.") + "_([0-9]{6,})\\.h5");
  std::map<int, std::string> written;
  for (const auto& entry : std::filesystem::directory_iterator(directory_)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || !std::regex_match(name, match, pattern)) continue;
    const int step = std::stoi(match[1].str());
    if (step > last_step)
      std::filesystem::remove(entry.path());
    else
      written[step] = entry.path().string();
  }
  steps_.clear();
  for (const auto& [step, path] : written) {
    Hdf5Handle handle = open_hdf5_file(path, xdmf_who);
    const Hdf5File file{handle.get(), path, xdmf_who};
    StepRecord record{step, read_double_dataset(file, "/time").at(0), {}};
    for (const MeshLayout& mesh : meshes_) {
      MeshStepRecord mesh_record{false, {}};
      const std::string group = "/" + mesh.name;
      if (has_dataset(file, group))
        for (const std::string& name : group_members(file, group)) {
          if (name == "coordinates") {
            mesh_record.moved = true;
            continue;
          }
          const std::vector<hsize_t> dimensions = dataset_dimensions(file, group + "/" + name);
          const int components = dimensions.size() == 2 ? static_cast<int>(dimensions[1]) : 1;
          const Center center = dimensions.at(0) == mesh.node_count ? Center::node : Center::cell;
          mesh_record.fields.push_back({name, center, components});
        }
      record.meshes.push_back(std::move(mesh_record));
    }
    steps_.push_back(std::move(record));
  }
  write_xdmf_files();
}

void XdmfTimeSeries::append_uniform_grid(std::string& xml, std::size_t mesh_index, const StepRecord* step,
                                         const std::string& indent) const {
  const MeshLayout& mesh = meshes_[mesh_index];
  const bool moved = step != nullptr && step->meshes[mesh_index].moved;
  const std::string mesh_file = basename_ + "_mesh.h5";
  const std::string step_file = step != nullptr ? file_name_of_step(step->step) : std::string();
  const std::string group = "/" + mesh.name;
  const std::string inner = indent + "  ";
  xml += indent + "<Grid Name=\"" + mesh.name + "\" GridType=\"Uniform\">\n";
  if (step != nullptr) xml += inner + "<Time Value=\"" + exact_decimal(step->time) + "\"/>\n";
  xml += inner + "<Topology TopologyType=\"" + xdmf_topology_type(mesh.cell_type) + "\" NumberOfElements=\"" +
         std::to_string(mesh.cell_count) + "\">\n";
  xml += data_item(inner + "  ", mesh.cell_count, nodes_per_cell(mesh.cell_type), true, mesh_file,
                   group + "/connectivity");
  xml += inner + "</Topology>\n";
  xml += inner + "<Geometry GeometryType=\"XYZ\">\n";
  xml += data_item(inner + "  ", mesh.node_count, 3, false, moved ? step_file : mesh_file, group + "/coordinates");
  xml += inner + "</Geometry>\n";
  if (step != nullptr) {
    for (const FieldRecord& field : step->meshes[mesh_index].fields) {
      xml += inner + "<Attribute Name=\"" + field.name + "\" AttributeType=\"" +
             (field.components == 1 ? "Scalar" : "Vector") + "\" Center=\"" +
             (field.center == Center::node ? "Node" : "Cell") + "\">\n";
      xml += data_item(inner + "  ", field.center == Center::node ? mesh.node_count : mesh.cell_count,
                       field.components, false, step_file, group + "/" + field.name);
      xml += inner + "</Attribute>\n";
    }
  }
  xml += indent + "</Grid>\n";
}

void XdmfTimeSeries::append_mesh_series(std::string& xml, std::size_t mesh_index, const std::string& name,
                                        const std::string& indent) const {
  if (steps_.empty()) {
    append_uniform_grid(xml, mesh_index, nullptr, indent);
    return;
  }
  xml += indent + "<Grid Name=\"" + name + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const StepRecord& step : steps_) append_uniform_grid(xml, mesh_index, &step, indent + "  ");
  xml += indent + "</Grid>\n";
}

std::string XdmfTimeSeries::xdmf_text(std::size_t only_mesh) const {
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      "  <Domain>\n";
  for (const auto& [key, value] : provenance_.attributes)
    xml += "    <Information Name=\"" + xml_escaped(key) + "\" Value=\"" + xml_escaped(value) + "\"/>\n";
  if (only_mesh != all_meshes) {
    append_mesh_series(xml, only_mesh, meshes_[only_mesh].name, "    ");
  } else if (meshes_.size() == 1) {
    append_mesh_series(xml, 0, basename_, "    ");
  } else {
    // One temporal collection per mesh, side by side: each mesh is one block, under one name,
    // at every step. (Per-step spatial collections would repeat the grid names at every step,
    // which the readers then number.)
    xml += "    <Grid Name=\"" + basename_ + "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
    for (std::size_t m = 0; m < meshes_.size(); ++m) append_mesh_series(xml, m, meshes_[m].name, "      ");
    xml += "    </Grid>\n";
  }
  xml += "  </Domain>\n</Xdmf>\n";
  return xml;
}

void XdmfTimeSeries::write_xdmf_files() const {
  for (std::size_t m = 0; m < meshes_.size(); ++m) write_file_atomically(mesh_xdmf_path(meshes_[m].name), xdmf_text(m));
  write_file_atomically(xdmf_path(), xdmf_text());
}

}  // namespace rouleau
