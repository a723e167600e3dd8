# `mpiexec -n RANKS featurepoints IN OUT` against `featurepoints IN OUT`: the output files must be
# byte-identical, and the summary must have the `ranks` line, which says who read the input (every
# rank its share of a binary PLY file's vertex rows; rank 0 any other file). Skipped (exit code 125) without
# mpiexec. Variables: WRITER (TestDistributedFeaturePoints), CLI (featurepoints), WORK (a folder),
# RANKS.
find_program(MPIEXEC NAMES mpiexec)
if(NOT MPIEXEC)
  message("mpiexec not found: skipped") # SKIP_REGULAR_EXPRESSION
  return()
endif()
file(MAKE_DIRECTORY "${WORK}")
set(_cloud "${WORK}/duplicates.ply")
set(_plate "${WORK}/plate.ply")
execute_process(COMMAND "${WRITER}" --write "${_cloud}" 20000 RESULT_VARIABLE _rc)
execute_process(COMMAND "${WRITER}" --write-plate "${_plate}" 20000 RESULT_VARIABLE _rc2)
if(NOT _rc EQUAL 0 OR NOT _rc2 EQUAL 0)
  message(FATAL_ERROR "cannot write ${_cloud} and ${_plate}")
endif()
# The plate again as a CSV file: read by rank 0 alone, then split.
set(_text "${WORK}/plate.csv")
execute_process(COMMAND "${WRITER}" --write-plate "${_text}" 20000 RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "cannot write ${_text}")
endif()
set(_root)
execute_process(COMMAND id -u OUTPUT_VARIABLE _uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(_uid STREQUAL "0")
  set(_root --allow-run-as-root)
endif()
# Each case: a name, the cloud, the options. The paper's method with its voxel pre-filter (the
# default) finds density contrast on the plate, none on the bracket.
foreach(_case "huang2023-off;${_cloud};--method;huang2023;--voxel-filter;off"
    "huang2023;${_cloud};--method;huang2023" "huang2023-plate;${_plate};--method;huang2023"
    "huang2023-text;${_text};--method;huang2023" "crease;${_cloud};--method;crease;--keep-copies")
  list(GET _case 0 _name)
  list(GET _case 1 _input)
  list(SUBLIST _case 2 -1 _options)
  file(REMOVE "${WORK}/${_name}-1.ply" "${WORK}/${_name}-${RANKS}.ply")
  execute_process(COMMAND "${CLI}" "${_input}" "${WORK}/${_name}-1.ply" ${_options} --quiet
    RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${_name}: featurepoints failed (${_rc})")
  endif()
  execute_process(COMMAND "${MPIEXEC}" --oversubscribe ${_root} -n ${RANKS} "${CLI}" "${_input}"
    "${WORK}/${_name}-${RANKS}.ply" ${_options} --threads 1
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _summary ERROR_VARIABLE _errors)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${_name}: mpiexec -n ${RANKS} featurepoints failed (${_rc}): ${_errors}")
  endif()
  if(_name STREQUAL "huang2023-text")
    set(_read "by rank 0")
  else()
    set(_read "by every rank")
  endif()
  if(NOT _summary MATCHES "ranks       ${RANKS}, the input read ${_read}")
    message(FATAL_ERROR "${_name}: no 'ranks ${RANKS}' line in the summary:\n${_summary}")
  endif()
  # Every case is split between the ranks (the default detector too), none run on rank 0 alone.
  if(_summary MATCHES "run on rank 0 alone")
    message(FATAL_ERROR "${_name}: not distributed:\n${_summary}")
  endif()
  file(SHA256 "${WORK}/${_name}-1.ply" _one)
  file(SHA256 "${WORK}/${_name}-${RANKS}.ply" _many)
  if(NOT _one STREQUAL _many)
    message(FATAL_ERROR "${_name}: the output of ${RANKS} ranks differs from one process's")
  endif()
  message("${_name}: ${RANKS} ranks give the same file as one process\n${_summary}")
endforeach()

# OUT.pvtp: each rank writes its piece; the pieces hold every point once, in ascending global ids,
# with one process's values.
file(REMOVE_RECURSE "${WORK}/pieces")
file(MAKE_DIRECTORY "${WORK}/pieces")
execute_process(COMMAND "${MPIEXEC}" --oversubscribe ${_root} -n ${RANKS} "${CLI}" "${_plate}"
  "${WORK}/pieces/plate.pvtp" --method huang2023 --threads 1 --quiet
  RESULT_VARIABLE _rc ERROR_VARIABLE _errors)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "pvtp: mpiexec -n ${RANKS} featurepoints failed (${_rc}): ${_errors}")
endif()
execute_process(COMMAND "${WRITER}" --compare-pvtp "${WORK}/pieces/plate.pvtp"
  "${WORK}/huang2023-plate-1.ply" ${RANKS} RESULT_VARIABLE _rc OUTPUT_VARIABLE _report)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "pvtp: the pieces differ from one process's output:\n${_report}")
endif()
message("pvtp: ${RANKS} pieces, the same values as one process\n${_report}")
