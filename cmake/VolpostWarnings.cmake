# SPDX-License-Identifier: MIT
# volpost_warnings(target): the project's warning set; errors under VOLPOST_STRICT_BUILD.
function(volpost_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual)
  if(VOLPOST_STRICT_BUILD)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
