#include "output/modes_h5.hpp"

#include "output/mode_display.hpp"
#include "output/text_file.hpp"
#include "output/xdmf.hpp"

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace coremodal {

namespace {

// ---------------------------------------------------------------------------
// HDF5 plumbing

// Owns one HDF5 identifier and closes it when it goes out of scope, so that an
// exception half-way through writing leaks nothing and leaves the file closed.
class Handle {
public:
    using Closer = herr_t (*)(hid_t);
    Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), closer_(other.closer_) {}
    Handle& operator=(Handle&&) = delete;
    ~Handle() {
        if (id_ >= 0) closer_(id_);
    }
    operator hid_t() const { return id_; }
    // Closes now and returns the status: closing a file flushes it, and that
    // failure (a full disk) must be reported, not swallowed by the destructor.
    herr_t close() {
        const herr_t status = id_ >= 0 ? closer_(id_) : 0;
        id_ = -1;
        return status;
    }

private:
    hid_t id_;
    Closer closer_;
};

// HDF5 prints its error stack to stderr by default. We report failures by
// exception instead (with the most specific HDF5 message), so silence the
// printing while we write and restore the caller's setting afterwards.
class QuietHdf5Errors {
public:
    QuietHdf5Errors() {
        H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
    QuietHdf5Errors(const QuietHdf5Errors&) = delete;
    QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;
    ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

private:
    H5E_auto2_t func_ = nullptr;
    void* data_ = nullptr;
};

// The most specific message on the current HDF5 error stack, e.g.
// "unable to open file: name = '/x/modes.h5', errno = 2, ...".
std::string hdf5_error_message() {
    std::string message;
    auto first_description = [](unsigned n, const H5E_error2_t* err, void* out) -> herr_t {
        auto* text = static_cast<std::string*>(out);
        if (n == 0 && err && err->desc) *text = err->desc;
        return 0;
    };
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, first_description, &message);
    H5Eclear2(H5E_DEFAULT);
    return message;
}

template <class T>
struct H5Types;
template <>
struct H5Types<double> {
    static hid_t memory() { return H5T_NATIVE_DOUBLE; }
    static hid_t file() { return H5T_IEEE_F64LE; }
};
template <>
struct H5Types<float> {
    static hid_t memory() { return H5T_NATIVE_FLOAT; }
    static hid_t file() { return H5T_IEEE_F32LE; }
};
template <>
struct H5Types<std::int64_t> {
    static hid_t memory() { return H5T_NATIVE_INT64; }
    static hid_t file() { return H5T_STD_I64LE; }
};
template <>
struct H5Types<std::int32_t> {
    static hid_t memory() { return H5T_NATIVE_INT32; }
    static hid_t file() { return H5T_STD_I32LE; }
};

// Datasets smaller than this are stored as they are: a chunk index and the
// filter headers would cost about as much as compression saves.
constexpr hsize_t kMinCompressedValues = 4096;
// Values per chunk: 512 KiB of doubles, inside HDF5's default 1 MiB chunk
// cache, so that a reader of a whole dataset inflates each chunk once.
constexpr hsize_t kChunkValues = 65536;

// Writes objects into one file; every failure becomes a runtime_error that
// names the file and what was being written.
class Writer {
public:
    explicit Writer(std::string path)
        : path_(std::move(path)), compress_(modes_h5_compression_available()) {}

    [[noreturn]] void fail(const std::string& what) const {
        std::string message = "cannot write " + path_ + ": " + what;
        const std::string detail = hdf5_error_message();
        if (!detail.empty()) message += " (HDF5: " + detail + ")";
        throw std::runtime_error(message);
    }
    hid_t check_id(hid_t id, const std::string& what) const {
        if (id < 0) fail(what);
        return id;
    }
    void check_status(herr_t status, const std::string& what) const {
        if (status < 0) fail(what);
    }

    // The file is built in memory (HDF5's core driver, no backing store)
    // and written to disk whole by write_image. HDF5 writing to a full disk
    // itself fails half-way and keeps the file open in the library, whose
    // clean-up in MPI_Finalize then crashes (SIGSEGV in H5F__close_cb;
    // issue 33, 6); a failed write of the image is an ordinary error.
    Handle create_file() const {
        Handle access(check_id(H5Pcreate(H5P_FILE_ACCESS), "file access properties"), H5Pclose);
        constexpr size_t kGrowBytes = size_t{4} << 20;  // the image grows 4 MiB at a time
        check_status(H5Pset_fapl_core(access, kGrowBytes, /*backing_store=*/0), "file access properties");
        return {check_id(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), "cannot create the file"),
                H5Fclose};
    }

    // The bytes of the file built in memory, then the file closed.
    std::string image(Handle& file) const {
        check_status(H5Fflush(file, H5F_SCOPE_LOCAL), "cannot flush the file");
        const ssize_t size = H5Fget_file_image(file, nullptr, 0);
        if (size < 0) fail("cannot take the file's image");
        std::string bytes(static_cast<size_t>(size), '\0');
        if (H5Fget_file_image(file, bytes.data(), bytes.size()) != size) fail("cannot take the file's image");
        check_status(file.close(), "cannot close the file");
        return bytes;
    }

    Handle group(hid_t parent, const std::string& name) const {
        return {check_id(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         "group " + name),
                H5Gclose};
    }

    // A numeric dataset of shape `dims` (row-major data).
    template <class T>
    void dataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
                 const T* data) const {
        Handle space(check_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                              "dataspace of " + name),
                     H5Sclose);
        Handle create = creation_properties(dims, name);
        Handle set(check_id(H5Dcreate2(parent, name.c_str(), H5Types<T>::file(), space,
                                       H5P_DEFAULT, create, H5P_DEFAULT),
                            "dataset " + name),
                   H5Dclose);
        if (element_count(dims) == 0) return;  // nothing to write; data may be null
        check_status(H5Dwrite(set, H5Types<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                     "dataset " + name);
    }

    template <class T>
    void vector_dataset(hid_t parent, const std::string& name, const std::vector<T>& values) const {
        dataset(parent, name, {values.size()}, values.data());
    }

    // A 1-D dataset of variable-length UTF-8 strings (h5py reads them as str
    // via .asstr()).
    void string_list(hid_t parent, const std::string& name,
                     const std::vector<std::string>& values) const {
        Handle type = string_type();
        const hsize_t n = values.size();
        Handle space(check_id(H5Screate_simple(1, &n, nullptr), "dataspace of " + name), H5Sclose);
        Handle set(check_id(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT,
                                       H5P_DEFAULT, H5P_DEFAULT),
                            "dataset " + name),
                   H5Dclose);
        if (values.empty()) return;
        std::vector<const char*> pointers;
        for (const std::string& v : values) pointers.push_back(v.c_str());
        check_status(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()),
                     "dataset " + name);
    }

    // A scalar string dataset: used for the case JSON, which may exceed the
    // 64 KiB that an attribute can hold.
    void string_scalar(hid_t parent, const std::string& name, const std::string& value) const {
        Handle type = string_type();
        Handle space(check_id(H5Screate(H5S_SCALAR), "dataspace of " + name), H5Sclose);
        Handle set(check_id(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT,
                                       H5P_DEFAULT, H5P_DEFAULT),
                            "dataset " + name),
                   H5Dclose);
        const char* pointer = value.c_str();
        check_status(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &pointer),
                     "dataset " + name);
    }

    void string_attribute(hid_t object, const std::string& name, const std::string& value) const {
        Handle type = string_type();
        Handle space(check_id(H5Screate(H5S_SCALAR), "dataspace of attribute " + name), H5Sclose);
        Handle attribute(check_id(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT,
                                             H5P_DEFAULT),
                                  "attribute " + name),
                         H5Aclose);
        const char* pointer = value.c_str();
        check_status(H5Awrite(attribute, type, &pointer), "attribute " + name);
    }

    void int_attribute(hid_t object, const std::string& name, std::int32_t value) const {
        Handle space(check_id(H5Screate(H5S_SCALAR), "dataspace of attribute " + name), H5Sclose);
        Handle attribute(check_id(H5Acreate2(object, name.c_str(), H5T_STD_I32LE, space,
                                             H5P_DEFAULT, H5P_DEFAULT),
                                  "attribute " + name),
                         H5Aclose);
        check_status(H5Awrite(attribute, H5T_NATIVE_INT32, &value), "attribute " + name);
    }

private:
    static hsize_t element_count(const std::vector<hsize_t>& dims) {
        hsize_t n = 1;
        for (hsize_t d : dims) n *= d;
        return n;
    }

    // Chunked, shuffled and deflated for large datasets when the library can;
    // the default (contiguous) layout otherwise. Chunks span whole rows.
    Handle creation_properties(const std::vector<hsize_t>& dims, const std::string& name) const {
        Handle plist(check_id(H5Pcreate(H5P_DATASET_CREATE), "properties of " + name), H5Pclose);
        if (!compress_ || element_count(dims) < kMinCompressedValues) return plist;
        std::vector<hsize_t> chunk = dims;
        const hsize_t row = element_count(dims) / dims[0];
        chunk[0] = std::clamp<hsize_t>(kChunkValues / row, 1, dims[0]);
        check_status(H5Pset_chunk(plist, static_cast<int>(chunk.size()), chunk.data()),
                     "chunks of " + name);
        // Shuffle groups the bytes of equal significance, which deflate then
        // finds far more repetition in (floating-point mode shapes: -8 %).
        check_status(H5Pset_shuffle(plist), "shuffle filter of " + name);
        check_status(H5Pset_deflate(plist, kModesH5DeflateLevel), "gzip filter of " + name);
        return plist;
    }

    Handle string_type() const {
        Handle type(check_id(H5Tcopy(H5T_C_S1), "string type"), H5Tclose);
        check_status(H5Tset_size(type, H5T_VARIABLE), "string type");
        check_status(H5Tset_cset(type, H5T_CSET_UTF8), "string type");
        return type;
    }

    std::string path_;
    bool compress_;
};

// ---------------------------------------------------------------------------
// The file's content

// Input problems are caught before the file is created, so that a bad call
// never leaves a half-written modes.h5 behind.
void check_input(const std::string& path, const Mesh& mesh, const std::vector<Mode>& modes) {
    auto fail = [&](const std::string& what) {
        throw std::runtime_error("cannot write " + path + ": " + what);
    };
    const size_t n_nodes = mesh.nodes.size();
    const size_t n_cells = mesh.cell_part.size();
    if (mesh.cells.size() != n_cells * mesh.nodes_per_cell())
        fail("the mesh has " + std::to_string(mesh.cells.size()) + " cell node indices for " +
             std::to_string(n_cells) + " cells of " + std::to_string(mesh.nodes_per_cell()) +
             " nodes");
    for (int node : mesh.cells)
        if (node < 0 || static_cast<size_t>(node) >= n_nodes)
            fail("cell node index " + std::to_string(node) + " is not a node of the mesh");
    for (int part : mesh.cell_part)
        if (part < 0 || static_cast<size_t>(part) >= mesh.part_names.size())
            fail("cell part " + std::to_string(part) + " has no entry in part_names");
    for (size_t k = 0; k < modes.size(); ++k)
        if (modes[k].shape.size() != 3 * n_nodes)
            fail("mode " + std::to_string(k + 1) + " has " +
                 std::to_string(modes[k].shape.size()) + " shape values, expected 3 x " +
                 std::to_string(n_nodes) + " nodes");
}

void write_mesh(const Writer& w, hid_t file, const Mesh& mesh) {
    static_assert(sizeof(std::array<double, 3>) == 3 * sizeof(double));
    Handle group = w.group(file, "mesh");
    const hsize_t n_nodes = mesh.nodes.size();
    const hsize_t n_cells = mesh.cell_part.size();
    const hsize_t per_cell = mesh.nodes_per_cell();

    w.dataset(group, "nodes", {n_nodes, 3},
              mesh.nodes.empty() ? nullptr : mesh.nodes.front().data());

    const std::vector<std::int64_t> cells(mesh.cells.begin(), mesh.cells.end());
    w.dataset(group, "cells", {n_cells, per_cell}, cells.data());
    {
        Handle cells_set(w.check_id(H5Dopen2(group, "cells", H5P_DEFAULT), "dataset cells"),
                         H5Dclose);
        w.string_attribute(cells_set, "cell_type", cell_type_name(mesh.cell_type));
    }
    const hsize_t vtk_per_cell = vtk_nodes_per_cell(mesh.cell_type);
    w.dataset(group, "vtk_cells", {n_cells, vtk_per_cell}, vtk_cells(mesh).data());

    const std::vector<std::int32_t> parts(mesh.cell_part.begin(), mesh.cell_part.end());
    w.vector_dataset(group, "cell_part", parts);
    w.string_list(group, "part_names", mesh.part_names);

    Handle groups = w.group(group, "node_groups");
    for (const auto& [name, nodes] : mesh.node_groups) {
        const std::vector<std::int64_t> indices(nodes.begin(), nodes.end());
        w.vector_dataset(groups, name, indices);
    }
}

// The shape of every mode in cylindrical components, as ParaView shows them
// (float32: they are for display; /modes/shapes holds the full precision).
void write_cylindrical(const Writer& w, hid_t modes_group, const Mesh& mesh,
                       const std::vector<Mode>& modes) {
    Handle u_r = w.group(modes_group, "u_r");
    Handle u_theta = w.group(modes_group, "u_theta");
    Handle u_z = w.group(modes_group, "u_z");
    auto as_float = [](const std::vector<double>& v) { return std::vector<float>(v.begin(), v.end()); };
    for (size_t k = 0; k < modes.size(); ++k) {
        const std::string path = modes_h5_component_dataset("u_r", static_cast<int>(k) + 1);
        const std::string name = path.substr(path.rfind('/') + 1);
        const CylindricalShape c = cylindrical_components(mesh, modes[k].shape);
        w.vector_dataset(u_r, name, as_float(c.u_r));
        w.vector_dataset(u_theta, name, as_float(c.u_theta));
        w.vector_dataset(u_z, name, as_float(c.u_z));
    }
}

// Every mode times its warp scale (float32, (N, 3)): what ParaView warps by
// at scale 1, so that Play steps through every mode drawn at a readable size
// (a bending mode's largest displacement 10 % of the length) without the
// scale being set mode by mode; /modes/shapes keeps the mass-normalised shape.
void write_display(const Writer& w, hid_t modes_group, const Mesh& mesh, const std::vector<Mode>& modes) {
    Handle display = w.group(modes_group, "display");
    for (size_t k = 0; k < modes.size(); ++k) {
        const std::string path = modes_h5_component_dataset("display", static_cast<int>(k) + 1);
        const double scale = suggested_warp_scale(mesh, modes[k].shape, modes[k].label.type);
        std::vector<float> scaled(modes[k].shape.size());
        for (size_t i = 0; i < scaled.size(); ++i) scaled[i] = static_cast<float>(scale * modes[k].shape[i]);
        w.dataset(display, path.substr(path.rfind('/') + 1), {scaled.size() / 3, 3}, scaled.data());
    }
}

void write_modes(const Writer& w, hid_t file, const Mesh& mesh, const std::vector<Mode>& modes) {
    Handle group = w.group(file, "modes");
    std::vector<double> frequency, eigenvalue, residual, share, effective_mass, warp_scale;
    std::vector<std::int32_t> n, m;
    std::vector<std::string> type;
    for (const Mode& mode : modes) {
        frequency.push_back(mode.frequency_hz);
        eigenvalue.push_back(mode.eigenvalue);
        residual.push_back(mode.relative_residual);
        type.push_back(mode.label.type);
        n.push_back(mode.label.n);
        m.push_back(mode.label.m);
        share.push_back(mode.label.dominant_share);
        const EffectiveMass& e = mode.effective_mass;
        effective_mass.insert(effective_mass.end(), {e.x, e.y, e.z, e.rz});
        warp_scale.push_back(suggested_warp_scale(mesh, mode.shape, mode.label.type));
    }
    w.vector_dataset(group, "frequency_hz", frequency);
    w.vector_dataset(group, "eigenvalue", eigenvalue);
    w.vector_dataset(group, "relative_residual", residual);
    w.string_list(group, "type", type);
    w.vector_dataset(group, "n", n);
    w.vector_dataset(group, "m", m);
    w.vector_dataset(group, "dominant_share", share);
    w.dataset(group, "effective_mass", {modes.size(), 4}, effective_mass.data());
    w.vector_dataset(group, "warp_scale", warp_scale);

    Handle shapes = w.group(group, "shapes");
    for (size_t k = 0; k < modes.size(); ++k) {
        const std::string dataset = modes_h5_shape_dataset(static_cast<int>(k) + 1);
        const std::string name = dataset.substr(dataset.rfind('/') + 1);
        w.dataset(shapes, name, {modes[k].shape.size() / 3, 3}, modes[k].shape.data());
    }
    write_cylindrical(w, group, mesh, modes);
    write_display(w, group, mesh, modes);
}

void write_file(const std::string& path, const Mesh& mesh, const std::vector<Mode>& modes,
                const std::string& case_name, const std::string& case_json,
                const std::string& program_version, bool& created) {
    const Writer w(path);
    Handle file = w.create_file();

    w.int_attribute(file, "schema_version", modes_h5_schema_version);
    const bool prefixed = program_version.rfind("coremodal", 0) == 0;
    w.string_attribute(file, "program", prefixed ? program_version
                                                 : "coremodal " + program_version);
    w.string_attribute(file, "case_name", case_name);
    {
        Handle case_group = w.group(file, "case");
        w.string_scalar(case_group, "json", case_json);
    }
    write_mesh(w, file, mesh);
    write_modes(w, file, mesh, modes);

    const std::string bytes = w.image(file);
    created = true;
    write_text_file(path, bytes);  // closed and checked: "No space left on device" is an error here
}

std::string mode_dataset_name(int number) {
    char name[32];
    std::snprintf(name, sizeof name, "mode_%04d", number);
    return name;
}

// A filter is usable when the library has it and may encode with it (a
// decode-only build reads compressed files but cannot write them).
bool filter_can_encode(H5Z_filter_t filter) {
    const QuietHdf5Errors quiet;
    unsigned config = 0;
    return H5Zfilter_avail(filter) > 0 && H5Zget_filter_info(filter, &config) >= 0 &&
           (config & H5Z_FILTER_CONFIG_ENCODE_ENABLED) != 0;
}

}  // namespace

std::string modes_h5_shape_dataset(int number) { return "/modes/shapes/" + mode_dataset_name(number); }

std::string modes_h5_component_dataset(const std::string& component, int number) {
    return "/modes/" + component + "/" + mode_dataset_name(number);
}

bool modes_h5_compression_available() {
    static const bool available = filter_can_encode(H5Z_FILTER_DEFLATE) && filter_can_encode(H5Z_FILTER_SHUFFLE);
    return available;
}

void write_modes_h5(const std::string& path, const Mesh& mesh, const std::vector<Mode>& modes,
                    const std::string& case_name, const std::string& case_json,
                    const std::string& program_version) {
    check_input(path, mesh, modes);
    const QuietHdf5Errors quiet;
    bool created = false;
    try {
        write_file(path, mesh, modes, case_name, case_json, program_version, created);
    } catch (...) {
        // Every handle is closed by now; don't leave a truncated file that a
        // reader could mistake for results (but never remove a file we did
        // not create, e.g. one locked by another program).
        if (created) std::remove(path.c_str());
        throw;
    }
}

}  // namespace coremodal
