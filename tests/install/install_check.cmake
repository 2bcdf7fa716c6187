# The installed programs work from PATH (README.md, "Installing"): `cmake --install BUILD
# --prefix PREFIX` into an empty folder, then, with PREFIX/bin first on PATH: `impact3d
# --version`, the installed example deck one_hex.dyn run to normal termination, and (when
# POST-IMPACT is built) `postimpact summary` of its database and a picture drawn with the
# default font (an absolute path into fonts-dejavu-core, whatever the prefix).
#
#   cmake -DBUILD=dir -DPREFIX=dir -DVERSION=x.y.z [-DPOSTIMPACT=ON] -P install_check.cmake
foreach(v BUILD PREFIX VERSION)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "install_check.cmake: -D${v}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}\n${err}")
endif()
set(docdir "${PREFIX}/share/doc/impact3d")
set(expected bin/impact3d bin/impact3d_deckgen share/doc/impact3d/README.md share/doc/impact3d/copyright
             share/doc/impact3d/LICENSE share/doc/impact3d/docs/developer-guide.md
             share/doc/impact3d/docs/messages.md share/doc/impact3d/examples/one_hex.dyn
             share/doc/impact3d/examples/taylor_bar.dyn share/doc/impact3d/examples/keyword/taylor_bar.k)
if(POSTIMPACT)
  list(APPEND expected bin/postimpact)
endif()
foreach(f ${expected})
  if(NOT EXISTS "${PREFIX}/${f}")
    message(FATAL_ERROR "not installed: ${PREFIX}/${f}\n${out}")
  endif()
endforeach()

# the installed programs, found through PATH
set(ENV{PATH} "${PREFIX}/bin:$ENV{PATH}")
execute_process(COMMAND sh -c "command -v impact3d" OUTPUT_VARIABLE found OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT found STREQUAL "${PREFIX}/bin/impact3d")
  message(FATAL_ERROR "impact3d on PATH is '${found}', not ${PREFIX}/bin/impact3d")
endif()
execute_process(COMMAND impact3d --version RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "^impact3d ${VERSION}")
  message(FATAL_ERROR "impact3d --version: exit ${rc}, '${out}${err}' (expected 'impact3d ${VERSION}')")
endif()

set(run "${PREFIX}/run_one_hex")
file(MAKE_DIRECTORY "${run}")
execute_process(COMMAND impact3d "i=${docdir}/examples/one_hex.dyn" o=d3hsp g=d3plot ncpu=1
                WORKING_DIRECTORY "${run}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "N o r m a l   t e r m i n a t i o n")
  message(FATAL_ERROR "installed impact3d on one_hex.dyn: exit ${rc}\n${out}\n${err}")
endif()
message(STATUS "installed impact3d: one_hex.dyn ran to normal termination")

if(POSTIMPACT)
  execute_process(COMMAND postimpact summary d3plot WORKING_DIRECTORY "${run}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\nsolids 1\n")
    message(FATAL_ERROR "installed postimpact summary: exit ${rc}\n${out}\n${err}")
  endif()
  # a picture with text: postimpact fails (exit 2) when its default font cannot be opened
  execute_process(COMMAND env -u POSTIMPACT_FONT postimpact d3plot --size 320x240 -o one_hex.png
                  WORKING_DIRECTORY "${run}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${run}/one_hex.png")
    message(FATAL_ERROR "installed postimpact picture: exit ${rc}\n${out}\n${err}")
  endif()
  message(STATUS "installed postimpact: summary and a picture with the default font")
endif()
