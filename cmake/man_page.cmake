# Writes asset-lint.1 (a man page) from the binary's --help text, so the installed page
# always matches the options of the binary it is installed with.
# Usage: cmake -DBINARY=... -DOUTPUT=... -DVERSION=... -P man_page.cmake
execute_process(COMMAND "${BINARY}" --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${BINARY} --help failed (${status})")
endif()
# roff: backslashes are escapes, and a line starting with '.' or '\'' would be a request.
string(REPLACE "\\" "\\e" help "${help}")
string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
set(page ".TH ASSET-LINT 1 \"\" \"asset-lint ${VERSION}\" \"User Commands\"
.SH NAME
asset-lint \\- lint and fix robot assets (URDF, USDA) for PhysX joint-drive physics
.SH SYNOPSIS
.B asset-lint
[\\fIcheck\\fR] [\\fIOPTIONS\\fR] \\fIPATH\\fR...
.br
.B asset-lint rule
\\fIRULE-ID\\fR
.SH DESCRIPTION
Checks URDF and USDA files against PhysX joint-tuning guidance and prints one finding per
line; \\fB--fix\\fR rewrites the offending values in place. Inline suppressions use the file's
comment syntax: \\fB<!-- asset-lint: ignore[rule-id] -->\\fR in URDF,
\\fB# asset-lint: ignore[rule-id]\\fR in USDA.
.SH OPTIONS
.nf
${help}.fi
.SH EXIT STATUS
0 nothing reported, 1 findings remain, 2 usage, configuration or I/O error.
.SH FILES
.I asset-lint.toml
in the checked file's directory or an ancestor.
")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" previous)
  if(previous STREQUAL page)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}" "${page}")
