# dpgen_add_adjoints(<target> KERNELS <file>... [TANGENTS] [COMPILE_ARGS <flag>...])
#
# Builds a static library <target> from the given annotated kernel files (the
# forward kernels, compiled as they are) and their adjoints, which dpgen
# generates at build time into ${CMAKE_CURRENT_BINARY_DIR}/<target>_generated/
# as <stem>_adjoint.{hpp,cpp}, and <stem>_kernels.hpp declaring the forward
# kernels. Link <target> and include "<stem>_adjoint.hpp".
# With TANGENTS, also the forward-mode kernels <stem>_tangent.{hpp,cpp}
# (<kernel>_tangent: Jacobian-vector products).
# Editing a kernel or rebuilding dpgen regenerates; an unchanged output is not
# rewritten, so nothing downstream rebuilds.
#
# The same file serves dpgen's own build, a parent project that adds dpgen
# with add_subdirectory or FetchContent, and an installed dpgen
# (find_package(dpgen CONFIG)): it runs the tool dpgen::dpgen and links
# dpgen::runtime, which carries the include path of dpgen/annotate.hpp,
# Eigen and OpenMP (for the generated code's pragmas).
include_guard(GLOBAL)

# The tool to run and what its commands depend on. In dpgen's build tree
# dpgen::dpgen is an alias of the tool target: depend on the target itself, so
# that rebuilding the tool regenerates. Installed, or given as DPGEN_GENERATOR,
# it is an imported executable: depend on its file.
function(_dpgen_tool out_tool out_dependency)
  get_target_property(tool dpgen::dpgen ALIASED_TARGET)
  if(tool)
    get_target_property(imported ${tool} IMPORTED)
    if(imported)
      set(tool)
    endif()
  endif()
  if(tool)
    set(${out_tool} ${tool} PARENT_SCOPE)
    set(${out_dependency} ${tool} PARENT_SCOPE)
  else()
    set(${out_tool} dpgen::dpgen PARENT_SCOPE)
    set(${out_dependency} $<TARGET_FILE:dpgen::dpgen> PARENT_SCOPE)
  endif()
endfunction()

function(dpgen_add_adjoints target)
  cmake_parse_arguments(ARG "TANGENTS" "" "KERNELS;COMPILE_ARGS" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "dpgen_add_adjoints(${target}): unexpected arguments "
                        "'${ARG_UNPARSED_ARGUMENTS}' (expected KERNELS <file>... "
                        "[TANGENTS] [COMPILE_ARGS <flag>...])")
  endif()
  if(NOT ARG_KERNELS)
    message(FATAL_ERROR "dpgen_add_adjoints(${target}): no KERNELS given")
  endif()
  foreach(needed dpgen::dpgen dpgen::runtime)
    if(NOT TARGET ${needed})
      message(FATAL_ERROR "dpgen_add_adjoints(${target}): target ${needed} does not exist here "
                          "(find_package(dpgen CONFIG) or add_subdirectory(<dpgen>) first)")
    endif()
  endforeach()
  _dpgen_tool(tool tool_dependency)
  set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_generated)
  file(MAKE_DIRECTORY ${gen_dir})
  set(generated)
  set(kernel_sources)
  set(kernel_dirs)
  foreach(kernel IN LISTS ARG_KERNELS)
    get_filename_component(abs ${kernel} ABSOLUTE)
    get_filename_component(stem ${kernel} NAME_WE)
    get_filename_component(kdir ${abs} DIRECTORY)
    set(hpp ${gen_dir}/${stem}_adjoint.hpp)
    set(cpp ${gen_dir}/${stem}_adjoint.cpp)
    set(stamp ${gen_dir}/${stem}_adjoint.stamp)
    set(tangent_files)
    set(tangent_flag)
    if(ARG_TANGENTS)
      set(tangent_files ${gen_dir}/${stem}_tangent.hpp ${gen_dir}/${stem}_tangent.cpp)
      set(tangent_flag --tangent)
    endif()
    # The stamp is the rule's output; the generated files are byproducts that
    # keep their timestamps when their content does not change.
    # dpgen writes ${stamp}.d listing every header the kernel includes, so
    # editing one of them regenerates too. The tool adds the include path of
    # dpgen/annotate.hpp itself.
    add_custom_command(
      OUTPUT ${stamp}
      BYPRODUCTS ${hpp} ${cpp} ${gen_dir}/${stem}_kernels.hpp ${tangent_files}
      COMMAND $<TARGET_FILE:${tool}> ${abs} --out-dir ${gen_dir} --stamp ${stamp} ${tangent_flag}
              -- -std=c++17 -I${kdir} ${ARG_COMPILE_ARGS}
      DEPENDS ${tool_dependency} ${abs}
      DEPFILE ${stamp}.d
      COMMENT "dpgen: adjoint of ${kernel}"
      VERBATIM)
    list(APPEND generated ${stamp} ${cpp} ${hpp} ${tangent_files})
    list(APPEND kernel_sources ${abs})
    list(APPEND kernel_dirs ${kdir})
  endforeach()
  list(REMOVE_DUPLICATES kernel_dirs)
  add_library(${target} STATIC ${kernel_sources} ${generated})
  # The generated headers include the headers of the kernels' view and object
  # classes as the kernel files spell them ("grid_view.hpp"): the kernels'
  # directories are on the include path of whoever includes them.
  target_include_directories(${target} PUBLIC ${gen_dir} ${kernel_dirs})
  target_link_libraries(${target} PUBLIC dpgen::runtime)
endfunction()

# dpgen_add_torch_ops(<target> KERNELS <file>... [SOURCES <file>...] [COMPILE_ARGS <flag>...]
#                     [NO_UNITY_BUILD])
#
# Builds a shared library <target> of PyTorch ops: for each kernel of the given files, the op
# torch.ops.dpgen.<kernel> (a torch::autograd::Function: forward = the kernel, on every thread
# where its nests set each element once (its IR printed into the op file), backward = its
# generated adjoint), which `dpgen --torch` generates at build time into
# ${CMAKE_CURRENT_BINARY_DIR}/<target>_generated/<stem>_torch.{hpp,cpp}. The kernels and their
# adjoints are the static library <target>_adjoints (dpgen_add_adjoints, position-independent).
# Load it from Python with torch.ops.load_library("<path of lib<target>.so>"), or link it from
# C++ (libtorch) and call dpgen::ops::<kernel>(...) from "<stem>_torch.hpp". SOURCES adds
# hand-written op sources (e.g. time loops or solves built on the same kernels). The
# generated op files are compiled as one translation unit (each includes torch's headers,
# ~15 s apiece); NO_UNITY_BUILD compiles them one by one (then an edit of one kernel
# file recompiles only its op file). Needs Torch (find_package(Torch) is called here if the
# parent has not).
function(dpgen_add_torch_ops target)
  cmake_parse_arguments(ARG "NO_UNITY_BUILD" "" "KERNELS;SOURCES;COMPILE_ARGS" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "dpgen_add_torch_ops(${target}): unexpected arguments "
                        "'${ARG_UNPARSED_ARGUMENTS}' (expected KERNELS <file>... "
                        "[SOURCES <file>...] [COMPILE_ARGS <flag>...] [NO_UNITY_BUILD])")
  endif()
  if(NOT ARG_KERNELS)
    message(FATAL_ERROR "dpgen_add_torch_ops(${target}): no KERNELS given")
  endif()
  if(NOT TORCH_LIBRARIES)
    find_package(Torch REQUIRED)
  endif()
  dpgen_add_adjoints(${target}_adjoints KERNELS ${ARG_KERNELS} COMPILE_ARGS ${ARG_COMPILE_ARGS})
  set_target_properties(${target}_adjoints PROPERTIES POSITION_INDEPENDENT_CODE ON)
  _dpgen_tool(tool tool_dependency)
  set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_generated)
  file(MAKE_DIRECTORY ${gen_dir})
  set(generated)
  foreach(kernel IN LISTS ARG_KERNELS)
    get_filename_component(abs ${kernel} ABSOLUTE)
    get_filename_component(stem ${kernel} NAME_WE)
    get_filename_component(kdir ${abs} DIRECTORY)
    set(hpp ${gen_dir}/${stem}_torch.hpp)
    set(cpp ${gen_dir}/${stem}_torch.cpp)
    set(stamp ${gen_dir}/${stem}_torch.stamp)
    add_custom_command(
      OUTPUT ${stamp}
      BYPRODUCTS ${hpp} ${cpp}
      COMMAND $<TARGET_FILE:${tool}> --torch ${abs} --out-dir ${gen_dir} --stamp ${stamp}
              -- -std=c++17 -I${kdir} ${ARG_COMPILE_ARGS}
      DEPENDS ${tool_dependency} ${abs}
      DEPFILE ${stamp}.d
      COMMENT "dpgen: PyTorch ops of ${kernel}"
      VERBATIM)
    list(APPEND generated ${stamp} ${cpp} ${hpp})
  endforeach()
  add_library(${target} SHARED ${generated} ${ARG_SOURCES})
  # The generated op files are compiled as one translation unit (a unity build of them
  # alone; SOURCES stay apart): each includes torch's headers, ~15 s of every file's compile
  # time, and what they define is named after their kernels (one op per kernel name).
  if(ARG_NO_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD OFF)
  else()
    set(op_sources ${generated})
    list(FILTER op_sources INCLUDE REGEX "\\.cpp$")
    set_source_files_properties(${op_sources} PROPERTIES UNITY_GROUP ops)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  endif()
  target_include_directories(${target} PUBLIC ${gen_dir})
  target_link_libraries(${target} PUBLIC ${target}_adjoints ${TORCH_LIBRARIES})
  # torch's headers bring their own warnings; the generated code is checked by its tests.
  set_target_properties(${target} PROPERTIES CXX_VISIBILITY_PRESET default)
endfunction()
