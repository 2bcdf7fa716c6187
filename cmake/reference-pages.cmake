# The manual's generated reference pages (the build target reference-pages): the text between
# the BEGIN and END markers of docs/keyword-tables.md and docs/card-tables.md is replaced by
# what impact3d --keyword-tables and --card-tables print (the reader's tables).  The tests
# KeywordCards.DocsPageIsTheGeneratedOne and FixedCards.ReadmeTablesAreTheGeneratedOnes fail
# while a committed page differs.
#   cmake -DIMPACT3D=build/impact3d -DSOURCE_DIR=. -P cmake/reference-pages.cmake
function(regenerate page option begin end)
  execute_process(COMMAND "${IMPACT3D}" ${option} OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${IMPACT3D} ${option} failed (${rc})")
  endif()
  file(READ "${SOURCE_DIR}/${page}" text)
  string(FIND "${text}" "${begin}" b)
  string(FIND "${text}" "${end}" e)
  if(b EQUAL -1 OR e EQUAL -1 OR e LESS b)
    message(FATAL_ERROR "${page}: the markers '${begin}' and '${end}' are missing")
  endif()
  string(LENGTH "${begin}" n)
  math(EXPR start "${b} + ${n}")
  string(SUBSTRING "${text}" 0 ${start} head)
  string(SUBSTRING "${text}" ${e} -1 tail)
  file(WRITE "${SOURCE_DIR}/${page}" "${head}${generated}${tail}")
  message(STATUS "${page}: regenerated from impact3d ${option}")
endfunction()

regenerate(docs/keyword-tables.md --keyword-tables "<!-- BEGIN keyword tables (impact3d --keyword-tables) -->\n" "<!-- END keyword tables -->")
regenerate(docs/card-tables.md --card-tables "<!-- BEGIN card tables (impact3d --card-tables) -->\n" "<!-- END card tables -->")
