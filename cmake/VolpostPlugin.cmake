# SPDX-License-Identifier: MIT
# volpost_add_plugin(NAME SOURCES ... [LIBRARIES ...]): one call builds a volpost plugin.
# The folder name, the target, the JSON id and the <NAME>.json metadata file agree.
# The metadata the plugin embeds is <NAME>.json plus "sdkVersion": the SDK it is built
# against, which the host checks before loading the library. In the source, write
#   Q_PLUGIN_METADATA(IID VOLPOST_READER_PLUGIN_IID FILE "<NAME>.meta.json")
# Used for the bundled plugins and, through the installed SDK, by in-house plugins.
function(volpost_add_plugin name)
  cmake_parse_arguments(P "" "" "SOURCES;LIBRARIES" ${ARGN})
  set(src_json ${CMAKE_CURRENT_SOURCE_DIR}/${name}.json)
  if(NOT EXISTS ${src_json})
    message(FATAL_ERROR "volpost plugin ${name}: ${name}.json metadata is missing")
  endif()
  file(READ ${src_json} meta)
  string(JSON id ERROR_VARIABLE err GET "${meta}" id)
  if(err OR NOT id STREQUAL name)
    message(FATAL_ERROR "volpost plugin ${name}: ${name}.json must have \"id\": \"${name}\"")
  endif()
  string(JSON meta SET "${meta}" sdkVersion
         "\"${VOLPOST_SDK_VERSION_MAJOR}.${VOLPOST_SDK_VERSION_MINOR}\"")
  set(meta_dir ${CMAKE_CURRENT_BINARY_DIR}/${name}_meta)
  file(WRITE ${meta_dir}/${name}.meta.json.tmp "${meta}")
  file(COPY_FILE ${meta_dir}/${name}.meta.json.tmp ${meta_dir}/${name}.meta.json ONLY_IF_DIFFERENT)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${src_json})

  add_library(${name} MODULE ${P_SOURCES})
  set_target_properties(${name} PROPERTIES PREFIX "" AUTOMOC ON)
  target_include_directories(${name} PRIVATE ${meta_dir})
  target_link_libraries(${name} PRIVATE ${P_LIBRARIES})
  if(TARGET volpost_core)  # building inside the volpost tree
    target_link_libraries(${name} PRIVATE volpost_plugin volpost_core)
    volpost_warnings(${name})
    set_target_properties(${name} PROPERTIES
      LIBRARY_OUTPUT_DIRECTORY ${VOLPOST_PLUGIN_BUILD_DIR}
      INSTALL_RPATH "$ORIGIN/../..")
    install(TARGETS ${name} LIBRARY DESTINATION ${VOLPOST_PLUGIN_INSTALL_DIR})
  else()
    target_link_libraries(${name} PRIVATE volpost::plugin volpost::core)
  endif()
endfunction()
