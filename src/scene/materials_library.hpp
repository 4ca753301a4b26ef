// Named materials a case file can use: material = "paperboard_core", or as the
// base of an inline table that overrides some values. Every value carries its
// source, and values that are rules of thumb rather than measurements are
// flagged, so a scene can list them as assumptions (docs/reference/material-sources.md).
#pragma once

#include "material/material.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

struct LibraryValue {
    std::string_view key;  // a case-file material key: "E_z", "nu_rz", "density", "E", "nu"
    double value;          // SI: Pa, 1, kg/m^3
    std::string_view source;
    bool assumed;  // rule of thumb rather than a measurement of this material
};

struct LibraryMaterial {
    std::string_view name;
    bool isotropic;  // values are E, nu, density; otherwise the ten orthotropic keys
    std::vector<LibraryValue> values;
};

// Case-file keys of an isotropic and of an orthotropic material, in the order
// of the documentation.
const std::vector<std::string_view>& isotropic_material_keys();    // E, nu, density
const std::vector<std::string_view>& orthotropic_material_keys();  // E_r ... density

const std::vector<LibraryMaterial>& material_library();
const LibraryMaterial* find_library_material(std::string_view name);

// The library entry as a material (isotropic entries expanded).
OrthotropicMaterial to_material(const LibraryMaterial& entry);

}  // namespace coremodal
