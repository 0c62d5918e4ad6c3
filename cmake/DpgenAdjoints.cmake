# dpgen_add_adjoints(<target> KERNELS <file>... [COMPILE_ARGS <flag>...])
#
# Builds a static library <target> from the given annotated kernel files (the
# forward kernels, compiled as they are) and their adjoints, which dpgen
# generates at build time into ${CMAKE_CURRENT_BINARY_DIR}/<target>_generated/
# as <stem>_adjoint.{hpp,cpp}. Link <target> and include "<stem>_adjoint.hpp".
# Editing a kernel or rebuilding dpgen regenerates; an unchanged output is not
# rewritten, so nothing downstream rebuilds.
function(dpgen_add_adjoints target)
  cmake_parse_arguments(ARG "" "" "KERNELS;COMPILE_ARGS" ${ARGN})
  if(NOT ARG_KERNELS)
    message(FATAL_ERROR "dpgen_add_adjoints(${target}): no KERNELS given")
  endif()
  set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_generated)
  file(MAKE_DIRECTORY ${gen_dir})
  get_target_property(runtime_inc dpgen_runtime INTERFACE_INCLUDE_DIRECTORIES)
  set(generated)
  set(kernel_sources)
  foreach(kernel IN LISTS ARG_KERNELS)
    get_filename_component(abs ${kernel} ABSOLUTE)
    get_filename_component(stem ${kernel} NAME_WE)
    get_filename_component(kdir ${abs} DIRECTORY)
    set(hpp ${gen_dir}/${stem}_adjoint.hpp)
    set(cpp ${gen_dir}/${stem}_adjoint.cpp)
    set(stamp ${gen_dir}/${stem}_adjoint.stamp)
    # The stamp is the rule's output; the generated files are byproducts that
    # keep their timestamps when their content does not change.
    # dpgen writes ${stamp}.d listing every header the kernel includes, so
    # editing one of them regenerates too.
    add_custom_command(
      OUTPUT ${stamp}
      BYPRODUCTS ${hpp} ${cpp}
      COMMAND $<TARGET_FILE:dpgen> ${abs} --out-dir ${gen_dir} --stamp ${stamp}
              -- -std=c++17 -I${runtime_inc} -I${kdir} ${ARG_COMPILE_ARGS}
      DEPENDS dpgen ${abs}
      DEPFILE ${stamp}.d
      COMMENT "dpgen: adjoint of ${kernel}"
      VERBATIM)
    list(APPEND generated ${stamp} ${cpp} ${hpp})
    list(APPEND kernel_sources ${abs})
  endforeach()
  add_library(${target} STATIC ${kernel_sources} ${generated})
  target_include_directories(${target} PUBLIC ${gen_dir})
  target_link_libraries(${target} PUBLIC dpgen_runtime OpenMP::OpenMP_CXX)
endfunction()
