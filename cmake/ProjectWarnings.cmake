# Warnings and sanitizers shared by every target of the project.
add_library(project_options INTERFACE)
target_compile_options(project_options INTERFACE -Wall -Wextra -Wpedantic -Wnon-virtual-dtor -Wcast-align)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(project_options INTERFACE -Wshadow=local)
else()
  # clang: shadowing of locals; "#pragma GCC unroll" is a hint it may decline on a loop it cannot count.
  target_compile_options(project_options INTERFACE -Wshadow-uncaptured-local -Wno-pass-failed)
endif()
if(PHIGS_WERROR)
  target_compile_options(project_options INTERFACE -Werror)
endif()
if(PHIGS_SANITIZE)
  # -O1 (after the build type's -O2, so it wins): with the sanitizers' instrumentation, -O2
  # compiles much slower for a run that is hardly faster.
  target_compile_options(project_options INTERFACE -fsanitize=address,undefined -O1
                                                    -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(project_options INTERFACE -fsanitize=address,undefined)
endif()
