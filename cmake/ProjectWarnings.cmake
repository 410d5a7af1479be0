# Warnings and sanitizers shared by every target of the project.
add_library(project_options INTERFACE)
target_compile_options(project_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local
                                                  -Wnon-virtual-dtor -Wcast-align)
if(PHIGS_WERROR)
  target_compile_options(project_options INTERFACE -Werror)
endif()
if(PHIGS_SANITIZE)
  target_compile_options(project_options INTERFACE -fsanitize=address,undefined
                                                    -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(project_options INTERFACE -fsanitize=address,undefined)
endif()
