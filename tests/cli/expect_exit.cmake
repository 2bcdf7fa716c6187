# Runs CMD (a ;-list) in DIR and checks its exit code (EXPECT_CODE) and that its combined output
# matches EXPECT_REGEX.  Used for command-line behaviour that GoogleTest does not cover.
file(MAKE_DIRECTORY ${DIR})
execute_process(COMMAND ${CMD} WORKING_DIRECTORY ${DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL EXPECT_CODE)
  message(FATAL_ERROR "exit code ${rc}, expected ${EXPECT_CODE}\n${out}\n${err}")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match '${EXPECT_REGEX}':\n${out}\n${err}")
endif()
if(DEFINED EXPECT_FILE AND NOT EXISTS ${DIR}/${EXPECT_FILE})
  message(FATAL_ERROR "${DIR}/${EXPECT_FILE} was not written")
endif()
