# Real meshes shipped by Debian packages. libcgal-demo ships its meshes inside a tarball, so the
# few we use are extracted into the build tree at configure time. Nothing here is committed.
set(INKWIRE_PACKAGED_DATA_DIR ${PROJECT_BINARY_DIR}/packaged-data)
set(INKWIRE_CGAL_DATA_TARBALL /usr/share/doc/libcgal-dev/data.tar.gz)
if(EXISTS ${INKWIRE_CGAL_DATA_TARBALL} AND NOT EXISTS ${INKWIRE_PACKAGED_DATA_DIR}/data/meshes/bull.off)
  file(ARCHIVE_EXTRACT INPUT ${INKWIRE_CGAL_DATA_TARBALL}
       DESTINATION ${INKWIRE_PACKAGED_DATA_DIR}
       PATTERNS data/meshes/bull.off data/meshes/cow.off data/meshes/camel.off
                data/meshes/triceratops.off data/meshes/elephant.off)
endif()
set(INKWIRE_MESH_DIR ${INKWIRE_PACKAGED_DATA_DIR}/data/meshes)
if(NOT EXISTS ${INKWIRE_MESH_DIR}/bull.off)
  message(WARNING "libcgal-demo meshes not found: the benchmark's default mesh and some tests will be unavailable (run scripts/setup.sh)")
endif()
