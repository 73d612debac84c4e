// inkwire-mesh-product: makes a product from a mesh into a data folder, for inkwire-server
// (its add-product --mesh, and sessions of its config with a mesh product), which runs it as a
// process of its own so that the serving process never loads GL (server/products/
// mesh_product_process.hpp). Says "pair D/T ..." per pair and "note: ..." per note on its
// standard output, its reason on failure, and exits 0 once the product is stored.
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "common/error.hpp"
#include "common/mesh_import.hpp"
#include "server/products/product_store.hpp"
#include "tools/mesh_product.hpp"

using namespace inkwire;

int main(int argc, char** argv) {
  std::string data, up = "auto";
  server::ProductSource source;
  MeshProductOptions& o = source.mesh_options;
  CLI::App app{"inkwire-mesh-product: a product rendered from a mesh, stored in a data folder (run by inkwire-server)"};
  app.add_option("--data", data, "the data folder")->required();
  app.add_option("--mesh", source.mesh, "the mesh")->required();
  app.add_option("--samples", o.samples, "samples on the ring");
  app.add_option("--sphere", o.sphere_level, "a geodesic sphere of samples instead (0-2; -1: a ring)");
  app.add_option("--size", o.size, "sample images are this many pixels square");
  app.add_option("--points", o.points, "exact control points per pair");
  app.add_option("--style", o.style, "the style the samples are rendered in");
  app.add_option("--up", up, "which axis is up in the mesh file: y, z or auto")->check(CLI::IsMember({"auto", "y", "z"}));
  CLI11_PARSE(app, argc, argv);
  try {
    o.up = parse_up_axis(up);
    server::AssetStore store(data);
    server::find_or_make_product(store, source, "mesh", [](int done, int total, const std::string& line) {
      if (done == 0) std::printf("note: %s\n", line.c_str());
      else std::printf("pair %d/%d %s\n", done, total, line.c_str());
      std::fflush(stdout);
    }, nullptr, product_from_mesh);
    return 0;
  } catch (const Error& e) {
    std::printf("%s\n", e.what());
    return 1;
  }
}
