#pragma once
// A product rendered from a mesh (SPEC T11): samples on a ring or a geodesic sphere, their
// render's alpha as mattes, exact control points from the mesh itself. This needs GL (an
// off-screen context of its own), so it lives in a library of its own that only the
// inkwire-mesh-product helper and the offline tools link: the serving process never loads GL,
// and a GL driver that crashes takes one helper down, not every session (mesh_product_process.hpp).
#include <filesystem>

#include "server/products/product.hpp"

namespace inkwire {

// Throws inkwire::Error.
Product product_from_mesh(const std::filesystem::path& mesh, const MeshProductOptions& options, const PairProgress& progress = {});

}  // namespace inkwire
