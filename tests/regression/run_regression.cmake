# One regression case: run impact3d on DECK into WORKDIR, then compare with the stored reference.
#
#   cmake -DIMPACT3D=... -DPOSTIMPACT=... -DDECK=file.dyn -DWORKDIR=dir -DTOL=tolerances.txt
#         -DMODE=plot|summary -DREF=path [-DUPDATE=ON] -P run_regression.cmake
#
# MODE plot:    REF is the reference folder holding d3plot, d3plot01, ...;
#               the check is `postimpact compare REF/d3plot WORKDIR/d3plot --tol TOL`.
# MODE summary: REF is the stored summary file;
#               the check is `postimpact summary WORKDIR/d3plot` then `postimpact
#               compare-summary REF WORKDIR/summary.txt --tol TOL`.
# UPDATE=ON:    instead of comparing, overwrite REF with this run (tools/update-regression-refs.sh).
#
# The run is the same for tests and updates: SOURCE_DATE_EPOCH=0 (reproducible run-time word),
# one thread, 8-byte plot words (so that the tolerances, not float32 rounding, decide).
foreach(v IMPACT3D POSTIMPACT DECK WORKDIR MODE REF)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "run_regression.cmake: -D${v}= is required")
  endif()
endforeach()
if(NOT UPDATE AND (NOT DEFINED TOL OR NOT EXISTS "${TOL}"))
  message(FATAL_ERROR "run_regression.cmake: tolerance file TOL='${TOL}' not found")
endif()

file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
set(ENV{SOURCE_DATE_EPOCH} 0)
execute_process(COMMAND "${IMPACT3D}" "i=${DECK}" o=d3hsp g=d3plot ncpu=1 plotwords=8
                WORKING_DIRECTORY "${WORKDIR}" RESULT_VARIABLE rc
                OUTPUT_FILE "${WORKDIR}/run.log" ERROR_FILE "${WORKDIR}/run.log")
if(NOT rc EQUAL 0)
  file(READ "${WORKDIR}/run.log" log)
  message(FATAL_ERROR "impact3d exited with ${rc} on ${DECK}:\n${log}")
endif()

if(MODE STREQUAL "plot")
  if(UPDATE)
    file(GLOB old "${REF}/d3plot*")
    if(old)
      file(REMOVE ${old})
    endif()
    file(MAKE_DIRECTORY "${REF}")
    file(GLOB new "${WORKDIR}/d3plot*")
    file(COPY ${new} DESTINATION "${REF}")
    message(STATUS "updated ${REF}")
    return()
  endif()
  execute_process(COMMAND "${POSTIMPACT}" compare "${REF}/d3plot" "${WORKDIR}/d3plot" --tol "${TOL}" --report 10
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "postimpact compare exited with ${rc}: the run differs from the reference ${REF} "
                        "(tools/update-regression-refs.sh updates the references when the change is intended)")
  endif()
elseif(MODE STREQUAL "summary")
  set(out "${WORKDIR}/summary.txt")
  if(UPDATE)
    set(out "${REF}")
  endif()
  execute_process(COMMAND "${POSTIMPACT}" summary "${WORKDIR}/d3plot" --printed "${WORKDIR}/d3hsp" -o "${out}"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "postimpact summary exited with ${rc}")
  endif()
  if(UPDATE)
    message(STATUS "updated ${REF}")
    return()
  endif()
  execute_process(COMMAND "${POSTIMPACT}" compare-summary "${REF}" "${out}" --tol "${TOL}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "postimpact compare-summary exited with ${rc}: the run differs from the summary ${REF} "
                        "(tools/update-regression-refs.sh updates the references when the change is intended)")
  endif()
else()
  message(FATAL_ERROR "run_regression.cmake: MODE must be plot or summary, not '${MODE}'")
endif()
