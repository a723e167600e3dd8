# CTest: install the project into a scratch prefix, build Examples/ against it with
# find_package(FeaturePoints) exactly as a user's project would, and run the example on a file:
# read, extract, write, render to PNG. Keeps the installed package and the example from rotting.
# With -DPYTHON (the interpreter) and -DPYTHON_DESTINATION, the installed Python package is
# imported from the prefix alone (no build tree on PYTHONPATH) and runs a reader and a detector.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DINPUT=... [-DX_COMMAND=sh|run-with-xvfb.sh]
#         [-DPYTHON=... -DPYTHON_DESTINATION=...] -P this
foreach(_var BUILD_DIR SOURCE_DIR WORK_DIR INPUT)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "${_var} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${_rc}):\n${_out}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

run_step("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/install")
file(GLOB_RECURSE _config "${WORK_DIR}/install/*/FeaturePointsConfig.cmake")
list(GET _config 0 _config)
get_filename_component(_config_dir "${_config}" DIRECTORY)
run_step("configure the example against the installed package" "${CMAKE_COMMAND}"
  -S "${SOURCE_DIR}/Examples" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=Release
  "-DFeaturePoints_DIR=${_config_dir}")
run_step("build the example" "${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
file(GLOB_RECURSE _libs "${WORK_DIR}/install/*libFeaturePointsFilters.so")
list(GET _libs 0 _lib)
get_filename_component(_lib_dir "${_lib}" DIRECTORY)
set(_run "${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${_lib_dir}"
  "${WORK_DIR}/build/FeaturePointsExample" "${WORK_DIR}/example.vtp" "${WORK_DIR}/example.png" "${INPUT}")
if(X_COMMAND)
  string(REPLACE "|" ";" _x_command "${X_COMMAND}")
  set(_run ${_x_command} ${_run})
endif()
run_step("run the installed example on ${INPUT}" ${_run})
foreach(_file example.vtp example.png)
  file(SIZE "${WORK_DIR}/${_file}" _size)
  if(_size LESS 1000)
    message(FATAL_ERROR "${_file}: ${_size} bytes, not a result")
  endif()
endforeach()
message(STATUS "installed example wrote example.vtp and example.png")

if(PYTHON)
  set(_site "${WORK_DIR}/install/${PYTHON_DESTINATION}")
  set(_script [=[
import sys
import featurepoints
from featurepoints import vtkCreaseVotingFeatures, vtkFeaturePointExtraction, vtkPointCloudReader
assert featurepoints.__file__.startswith(sys.argv[1]), featurepoints.__file__
reader = vtkPointCloudReader()
reader.SetFileName(sys.argv[2])
features = vtkCreaseVotingFeatures()
features.SetInputConnection(reader.GetOutputPort())
features.Update()
assert features.GetNumberOfFeaturePoints() == 559, features.GetNumberOfFeaturePoints()
print("installed featurepoints:", featurepoints.__file__)
]=])
  run_step("import the installed Python package from ${_site}" "${CMAKE_COMMAND}" -E env
    "PYTHONPATH=${_site}" "${PYTHON}" -c "${_script}" "${_site}" "${INPUT}")
endif()
