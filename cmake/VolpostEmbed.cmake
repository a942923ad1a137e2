# SPDX-License-Identifier: MIT
# volpost_embed_text(OUTPUT out.cpp NAMESPACE ns FUNCTION fn FILES a.glsl b.glsl BASE dir)
# writes a C++ source with a function `const std::map<std::string, std::string_view>& fn()`
# that maps each file's path (relative to BASE) to its contents. Shaders are embedded this
# way so the binary needs no files at run time.
function(volpost_embed_text)
  cmake_parse_arguments(E "" "OUTPUT;NAMESPACE;FUNCTION;BASE" "FILES" ${ARGN})
  add_custom_command(OUTPUT ${E_OUTPUT}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${E_OUTPUT} -DNAMESPACE=${E_NAMESPACE}
            -DFUNCTION=${E_FUNCTION} -DBASE=${E_BASE} "-DFILES=${E_FILES}"
            -P ${PROJECT_SOURCE_DIR}/cmake/VolpostEmbedScript.cmake
    DEPENDS ${E_FILES} ${PROJECT_SOURCE_DIR}/cmake/VolpostEmbedScript.cmake
    COMMENT "Embedding ${E_FUNCTION}"
    VERBATIM)
endfunction()
