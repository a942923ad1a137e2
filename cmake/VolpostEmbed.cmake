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
            -P ${_VOLPOST_EMBED_DIR}/VolpostEmbedScript.cmake
    DEPENDS ${E_FILES} ${_VOLPOST_EMBED_DIR}/VolpostEmbedScript.cmake
    COMMENT "Embedding ${E_FUNCTION}"
    VERBATIM)
endfunction()
set(_VOLPOST_EMBED_DIR ${CMAKE_CURRENT_LIST_DIR})

# volpost_embed_shaders(TARGET NAMESPACE ns DIR shaders): every .glsl/.vert/.frag/.geom/
# .comp file under DIR is embedded into TARGET, which gets the function
#   const std::map<std::string, std::string_view>& ns::embeddedShaders();
# to hand to volpost::gl::registerShaders(prefix, ns::embeddedShaders()). Used by the host,
# the bundled plugins and, through the installed SDK, by in-house renderers.
function(volpost_embed_shaders target)
  cmake_parse_arguments(S "" "NAMESPACE;DIR" "" ${ARGN})
  file(GLOB_RECURSE files CONFIGURE_DEPENDS
    ${S_DIR}/*.glsl ${S_DIR}/*.vert ${S_DIR}/*.frag ${S_DIR}/*.geom ${S_DIR}/*.comp)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${target}_EmbeddedShaders.cpp)
  volpost_embed_text(OUTPUT ${out} NAMESPACE ${S_NAMESPACE} FUNCTION embeddedShaders
    BASE ${S_DIR} FILES ${files})
  target_sources(${target} PRIVATE ${out})
endfunction()
