# Writes gzipped man pages with help2man from the programs' own --help and --version:
# ydscope.1, ydscope-cli.1 and ydscope-cli-COMMAND.1 for every command ydscope-cli lists.
#   cmake -DHELP2MAN=... -DGZIP=... -DVERSION=... -DCLI=... [-DAPP=...] -DOUT=dir -P man_pages.cmake
file(MAKE_DIRECTORY ${OUT})
file(GLOB old ${OUT}/*.1.gz)
if(old)
  file(REMOVE ${old})
endif()

# man_page(PAGE "PROGRAM [COMMAND]" "one-line description")
function(man_page page program description)
  execute_process(
    COMMAND ${HELP2MAN} --no-info --section=1 --manual "User Commands" --source "ydscope ${VERSION}"
            --name "${description}" --output ${OUT}/${page}.1 "${program}"
    RESULT_VARIABLE failed ERROR_VARIABLE error)
  if(failed)
    message(FATAL_ERROR "help2man failed for ${program}: ${error}")
  endif()
  # help2man titles a page after the program's first word; a command gets its own title and name.
  file(READ ${OUT}/${page}.1 text)
  string(TOUPPER "${page}" title)
  string(REGEX REPLACE "\n\\.TH [^ ]+ " "\n.TH ${title} " text "${text}")
  string(REGEX REPLACE "\n\\.SH NAME\n[^\n]*\n" "\n.SH NAME\n${page} \\\\- ${description}\n" text "${text}")
  file(WRITE ${OUT}/${page}.1 "${text}")
  # -n: no name or time stamp inside, so the same build gives the same bytes.
  execute_process(COMMAND ${GZIP} -9nf ${OUT}/${page}.1 RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "gzip failed on ${OUT}/${page}.1")
  endif()
endfunction()

if(APP)
  man_page(ydscope "${APP}" "real-time viewer for YDLIDAR G1, G6 and TG-series lidars")
endif()
man_page(ydscope-cli "${CLI}" "headless toolkit for YDLIDAR G1, G6 and TG-series lidars")

# The commands and their summaries, from the overview's "commands:" list.
execute_process(COMMAND ${CLI} --help OUTPUT_VARIABLE overview RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${CLI} --help failed")
endif()
string(REGEX MATCH "commands:\n(  [^\n]+\n)+" list "${overview}")
string(REGEX MATCHALL "  [a-z]+ +[^\n]+" lines "${list}")
foreach(line ${lines})
  string(REGEX MATCH "^  ([a-z]+) +(.+)$" _ "${line}")
  man_page(ydscope-cli-${CMAKE_MATCH_1} "${CLI} ${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}")
endforeach()
