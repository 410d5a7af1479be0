# Every dependency comes from a Debian 12 package; a missing one stops the configure step
# with the name of the package to install.
find_package(PkgConfig)

macro(require_found found_var package what)
  if(NOT ${found_var})
    message(FATAL_ERROR "${what} not found: install the Debian package '${package}' "
                        "(apt-get install ${package}), or run scripts/setup.sh")
  endif()
endmacro()

find_package(glm CONFIG QUIET)
require_found(glm_FOUND libglm-dev "GLM")

find_package(PNG QUIET)
require_found(PNG_FOUND libpng-dev "libpng")

find_package(Vulkan QUIET)
require_found(Vulkan_FOUND libvulkan-dev "Vulkan headers and loader")

find_program(GLSLANG_VALIDATOR glslangValidator)
require_found(GLSLANG_VALIDATOR glslang-tools "glslangValidator")

# The renderer specialises its shaders with the SPIRV-Tools optimiser (phigs/src/vk/ShaderSpecialisation.cpp).
find_package(SPIRV-Tools-opt CONFIG QUIET)
require_found(SPIRV-Tools-opt_FOUND spirv-tools "SPIRV-Tools (optimiser library)")

find_package(glfw3 CONFIG QUIET)
require_found(glfw3_FOUND libglfw3-dev "GLFW 3")

if(PHIGS_BUILD_TESTS)
  find_package(Catch2 2 CONFIG QUIET)
  require_found(Catch2_FOUND catch2 "Catch2")
endif()

# Render tests need the lavapipe driver and the Khronos validation layer at run time.
# Debian names the manifest after the architecture (lvp_icd.x86_64.json, lvp_icd.aarch64.json, ...).
file(GLOB lavapipe_manifests /usr/share/vulkan/icd.d/lvp_icd.*.json)
list(SORT lavapipe_manifests)
set(lavapipe_default "/usr/share/vulkan/icd.d/lvp_icd.${CMAKE_SYSTEM_PROCESSOR}.json")
if(NOT EXISTS "${lavapipe_default}" AND lavapipe_manifests)
  list(GET lavapipe_manifests 0 lavapipe_default)
endif()
set(PHIGS_LAVAPIPE_ICD "${lavapipe_default}" CACHE FILEPATH "Vulkan ICD manifest of Mesa lavapipe")
if(NOT EXISTS "${PHIGS_LAVAPIPE_ICD}")
  message(FATAL_ERROR "Mesa lavapipe not found at ${PHIGS_LAVAPIPE_ICD}: install the Debian "
                      "package 'mesa-vulkan-drivers'")
endif()
if(NOT EXISTS "/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json")
  message(FATAL_ERROR "Vulkan validation layer not found: install the Debian package "
                      "'vulkan-validationlayers'")
endif()

# phigs_hardcopy writes PDF, SVG and EPS through cairo's file surfaces; its tests rasterise the
# files with poppler's pdftoppm (and list images with pdfimages) and librsvg's rsvg-convert.
require_found(PKG_CONFIG_FOUND pkg-config "pkg-config")
pkg_check_modules(CAIRO QUIET IMPORTED_TARGET cairo cairo-pdf cairo-svg cairo-ps)
require_found(CAIRO_FOUND libcairo2-dev "cairo with its PDF, SVG and PostScript surfaces")
if(PHIGS_BUILD_TESTS)
  find_program(PDFTOPPM pdftoppm)
  require_found(PDFTOPPM poppler-utils "pdftoppm (the vector hardcopy tests rasterise PDF files with it)")
  find_program(PDFIMAGES pdfimages)
  require_found(PDFIMAGES poppler-utils "pdfimages (the vector hardcopy tests check PDF files hold no image)")
  find_program(RSVG_CONVERT rsvg-convert)
  require_found(RSVG_CONVERT librsvg2-bin "rsvg-convert (the vector hardcopy tests rasterise SVG files with it)")
endif()

# geom_exchange (geom/exchange) writes and reads IGES and STEP through OpenCASCADE's data
# exchange. Debian's config defines a module's targets only where its -dev package is installed,
# so each needed target is checked and a missing one names its package.
find_package(OpenCASCADE CONFIG QUIET COMPONENTS FoundationClasses ModelingData ModelingAlgorithms
             ApplicationFramework DataExchange)
foreach(occt_need IN ITEMS "TKMath;libocct-foundation-dev" "TKG3d;libocct-modeling-data-dev"
                           "TKTopAlgo;libocct-modeling-algorithms-dev" "TKLCAF;libocct-ocaf-dev"
                           "TKXDESTEP;libocct-data-exchange-dev" "TKXDEIGES;libocct-data-exchange-dev")
  list(GET occt_need 0 occt_target)
  list(GET occt_need 1 occt_package)
  set(occt_found FALSE)
  if(TARGET ${occt_target})
    set(occt_found TRUE)
  endif()
  require_found(occt_found ${occt_package} "OpenCASCADE library ${occt_target}")
endforeach()
# TKernel's imported target names libtbb.so by path, which Debian's OCCT packages do not pull in.
get_target_property(occt_kernel_links TKernel INTERFACE_LINK_LIBRARIES)
foreach(occt_link IN LISTS occt_kernel_links)
  set(occt_found TRUE)
  if(IS_ABSOLUTE "${occt_link}" AND NOT EXISTS "${occt_link}")
    set(occt_found FALSE)
  endif()
  require_found(occt_found libtbb-dev "${occt_link} (named by OpenCASCADE)")
endforeach()
