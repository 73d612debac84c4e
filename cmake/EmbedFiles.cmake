# inkwire_embed_files(TARGET <target> BASE <dir> [FUNCTION <name>] FILES <files...>)
# Generates a C++ source defining inkwire::<name>() (default embedded_files), a map holding every
# file as a string by its path relative to BASE (e.g. "default/mesh.vert"). Regenerated at build
# time when any file changes.
set(INKWIRE_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_files_script.cmake)

function(inkwire_embed_files)
  cmake_parse_arguments(ARG "" "TARGET;BASE;FUNCTION" "FILES" ${ARGN})
  if(NOT ARG_FUNCTION)
    set(ARG_FUNCTION embedded_files)
  endif()
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}_${ARG_FUNCTION}.cpp)
  string(REPLACE ";" "|" files_arg "${ARG_FILES}")  # a list would split into several arguments
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DBASE=${ARG_BASE} -DFUNCTION=${ARG_FUNCTION} "-DFILES=${files_arg}"
            -P ${INKWIRE_EMBED_SCRIPT}
    DEPENDS ${ARG_FILES} ${INKWIRE_EMBED_SCRIPT}
    COMMENT "Embedding ${ARG_TARGET} files" VERBATIM)
  target_sources(${ARG_TARGET} PRIVATE ${out})
endfunction()
