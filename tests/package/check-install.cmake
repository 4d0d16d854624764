# ctest -P script: installs the build tree into a temporary prefix, then configures, builds and runs
# examples/cmake-consumer against it (find_package(ssimarch CONFIG)) and checks the pkg-config file.
# -D BUILD_DIR, SOURCE_DIR, WORK_DIR, CXX (the compiler of the pkg-config check), and PYTHON and
# PYTHON_DIR (the interpreter and the package's install directory) where the module is built.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f include/ssimarch/pipeline/trace_job.hpp lib/cmake/ssimarch/ssimarchConfig.cmake lib/pkgconfig/ssimarch.pc)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cmake-consumer -B ${WORK_DIR}/consumer -G Ninja
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/viviani_length ${SOURCE_DIR}/examples/viviani.json)
# Viviani's curve, sphere radius 2 and cylinder radius 1: length 8 sqrt(2) E(1/sqrt 2) = 15.28079...
if(NOT out MATCHES "viviani [0-9]+ 15\\.28")
  message(FATAL_ERROR "unexpected output of the consumer: ${out}")
endif()
# The build tree is a package too (issue 29): the consumer configured with CMAKE_PREFIX_PATH=<build>.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cmake-consumer -B ${WORK_DIR}/consumer-build-tree -G Ninja
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${BUILD_DIR})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer-build-tree)
run(${WORK_DIR}/consumer-build-tree/viviani_length ${SOURCE_DIR}/examples/viviani.json)
if(NOT out MATCHES "viviani [0-9]+ 15\\.28")
  message(FATAL_ERROR "unexpected output of the consumer built against the build tree: ${out}")
endif()
# pkg-config: the flags name the installed headers and libraries, and the consumer's source compiles,
# links and runs with exactly `c++ main.cpp $(pkg-config --cflags --libs ssimarch)`.
find_program(PKG_CONFIG pkg-config)
if(NOT PKG_CONFIG)
  message(FATAL_ERROR "pkg-config is needed to check ssimarch.pc (scripts/install-deps installs it)")
endif()
set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
run(${PKG_CONFIG} --variable=includedir ssimarch)
string(STRIP "${out}" includedir)
if(NOT EXISTS ${includedir}/ssimarch/pipeline/trace_job.hpp)
  message(FATAL_ERROR "pkg-config includedir ${includedir} does not hold the installed headers")
endif()
run(${PKG_CONFIG} --cflags --libs ssimarch)
if(NOT out MATCHES "-lssimarch_pipeline")
  message(FATAL_ERROR "pkg-config flags: ${out}")
endif()
separate_arguments(pc_flags UNIX_COMMAND "${out}")
run(${CXX} -O1 ${SOURCE_DIR}/examples/cmake-consumer/main.cpp -o ${WORK_DIR}/viviani_length_pkg_config ${pc_flags})
run(${WORK_DIR}/viviani_length_pkg_config ${SOURCE_DIR}/examples/viviani.json)
if(NOT out MATCHES "viviani [0-9]+ 15\\.28")
  message(FATAL_ERROR "unexpected output of the consumer built with pkg-config's flags: ${out}")
endif()
# The Python package installed beside the libraries imports from the prefix and evaluates.
if(PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
  # One statement a line: run() passes its arguments as a list, which a ';' would split.
  run(${PYTHON} -c "import pathlib
import ssimarch
p = pathlib.Path(ssimarch.__file__).parent
assert str(p).startswith('${prefix}'), p
assert (p / 'py.typed').exists() and (p / '__init__.pyi').exists()
print(round(float(ssimarch.Sphere([0, 0, 0], 2).point(0.0, 0.0)[0]), 12))")
  if(NOT out MATCHES "^2\\.0")
    message(FATAL_ERROR "the installed Python package: ${out}")
  endif()
endif()
message(STATUS "consumer output: ${out}")
