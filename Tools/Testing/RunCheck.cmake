# Runs a command and checks its exit status and its output (a ctest helper).
#
#   cmake [-DEXPECT=success|failure] [-DEXIT_CODE=N] [-DREGEX=re] [-DFORBID=re]
#         [-DMAKE_FILE=path -DMAKE_FILE_KIND=junk|points-only|ascii-ply-no-face|ushort-ply|
#                                           float-color-grid|strip|face-color-ply|
#                                           ply-extras|ply-no-index-list|ply-long-face|
#                                           ascii-vtk-cut|stl-cut|stl-bogus-count|
#                                           string-array-vtk|link-dev-full|folder|
#                                           truncated -DMAKE_FILE_FROM=path -DMAKE_FILE_SIZE=n]
#         [-DCHECK_FILE=path -DCHECK_FILE_REGEX=re] [-DCHECK_FILE_ABSENT=path] [-DFRESH=path;...]
#         [-DALLOW_RAW_VTK=ON]
#         -P RunCheck.cmake -- COMMAND [ARG ...]
#
# EXPECT: success (exit 0, the default) or failure (exit status not 0; EXIT_CODE pins it).
# REGEX must match and FORBID must not match the command's stdout + stderr, which must hold no
# raw VTK message ("ERROR: In ...", "Warning: In ...", a logger's "ERR|" or "WARN|") unless
# ALLOW_RAW_VTK is on.
# MAKE_FILE is written before the command runs: "junk" is text that is no mesh format,
# "points-only" a legacy VTK polydata with three vertices and no triangle, "ascii-ply-no-face"
# an ASCII PLY whose header announces a face its body lacks, "ushort-ply" an ASCII PLY with
# 16-bit colours, "float-color-grid" a legacy VTK flat 6 x 6 grid of triangles whose float RGB
# colours lie in [1, 2] but for one inner point at 9 (so not in [0, 1]: mapped by their
# range), "strip" a legacy VTK polydata of one triangle strip (8 points, 6 triangles),
# "face-color-ply" an ASCII PLY of two triangles coloured per face, "ply-extras" a valid ASCII
# PLY with comments, obj_info, CRLF line ends, extra spaces, a uint8/int32 list and a material
# element with float colours (which VTK's reader does not read as point colours),
# "ply-no-index-list" one whose faces have no vertex_indices list, "ply-long-face" one face of
# 300 corners, "ascii-vtk-cut" an ASCII legacy VTK polydata whose second triangle is cut short
# (VTK's reader crashed on it), "stl-bogus-count" a binary STL of two
# whole triangles (4 points) whose header counts 16,843,009, "stl-cut" the same with 20 bytes
# of a third triangle, "string-array-vtk" a legacy VTK polydata of two triangles with a point
# array of text named Labels, "link-dev-full" a symbolic link to /dev/full (a full disk),
# "folder" an empty folder, "truncated" the first MAKE_FILE_SIZE bytes of MAKE_FILE_FROM.
# CHECK_FILE must exist after the command and match CHECK_FILE_REGEX (it is removed first,
# unless it is MAKE_FILE: a file from an earlier run cannot pass); CHECK_FILE_ABSENT must not
# (it is removed first too). Each FRESH file, a file the command writes for later checks, is
# removed first and must exist after.
# A failed check: its text on one line (message(FATAL_ERROR) wraps long ones, which the checks
# of this script's own messages could not match), then the end.
function (check_failed text)
  message(STATUS "RunCheck: ${text}")
  message(FATAL_ERROR "RunCheck: the check failed")
endfunction ()

set(command)
set(after_separator FALSE)
foreach (i RANGE 1 ${CMAKE_ARGC})
  if (i EQUAL CMAKE_ARGC)
    break ()
  endif ()
  if (after_separator)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif (CMAKE_ARGV${i} STREQUAL "--")
    set(after_separator TRUE)
  endif ()
endforeach ()
if (NOT command)
  check_failed("RunCheck.cmake: no command given after --")
endif ()
if (NOT DEFINED EXPECT)
  set(EXPECT success)
endif ()

if (DEFINED MAKE_FILE)
  if (MAKE_FILE_KIND STREQUAL "junk")
    file(WRITE "${MAKE_FILE}" "this is plain text, not a mesh\n1 2 3\n")
  elseif (MAKE_FILE_KIND STREQUAL "points-only")
    file(WRITE "${MAKE_FILE}"
      "# vtk DataFile Version 3.0\npoints and no triangle\nASCII\nDATASET POLYDATA\n"
      "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nVERTICES 1 4\n3 0 1 2\n")
  elseif (MAKE_FILE_KIND MATCHES "^(ascii-ply-no-face|ushort-ply)$")
    set(type uchar)
    set(face "3 0 1 2\n")
    if (MAKE_FILE_KIND STREQUAL "ascii-ply-no-face")
      set(face "")
    else ()
      set(type ushort)
    endif ()
    file(WRITE "${MAKE_FILE}"
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty ${type} red\nproperty ${type} green\nproperty ${type} blue\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0 1000 2 3\n1 0 0 4 5 6\n0 1 0 7 8 9\n${face}")
  elseif (MAKE_FILE_KIND STREQUAL "float-color-grid")
    set(points "")
    set(colors "")
    set(cells "")
    foreach (y RANGE 5)
      foreach (x RANGE 5)
        string(APPEND points "${x} ${y} 0\n")
        if (x EQUAL 2 AND y EQUAL 3)
          string(APPEND colors "9 9 9\n")
        else ()
          math(EXPR r "10 + 2 * ${x}")
          math(EXPR g "10 + 2 * ${y}")
          string(APPEND colors "1.${r} 1.${g} 1.5\n")
        endif ()
        if (x LESS 5 AND y LESS 5)
          math(EXPR a "6 * ${y} + ${x}")
          math(EXPR b "${a} + 1")
          math(EXPR c "${a} + 7")
          math(EXPR d "${a} + 6")
          string(APPEND cells "3 ${a} ${b} ${c}\n3 ${a} ${c} ${d}\n")
        endif ()
      endforeach ()
    endforeach ()
    file(WRITE "${MAKE_FILE}"
      "# vtk DataFile Version 3.0\nfloat colours\nASCII\nDATASET POLYDATA\n"
      "POINTS 36 float\n${points}POLYGONS 50 200\n${cells}"
      "POINT_DATA 36\nSCALARS RGB float 3\nLOOKUP_TABLE default\n${colors}")
  elseif (MAKE_FILE_KIND STREQUAL "ascii-vtk-cut")
    file(WRITE "${MAKE_FILE}"
      "# vtk DataFile Version 3.0\ncut short\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
      "0 0 0 1 0 0 0 1 0 1 1 0\nPOLYGONS 2 8\n3 0 1 2\n3 1")
  elseif (MAKE_FILE_KIND MATCHES "^stl-(cut|bogus-count)$")
    # Bytes without a zero, which file(WRITE) cannot write: as floats, e is 2.4e-38 and o is
    # 1.0078; the header's 84 bytes of 1 count 16,843,009 triangles.
    string(ASCII 1 1 1 1 e)
    string(ASCII 1 1 129 63 o)
    string(ASCII 1 1 attribute)
    string(REPEAT "${e}" 21 header)
    set(first "${e}${e}${e}${e}${e}${e}${o}${e}${e}${e}${o}${e}${attribute}")
    set(second "${e}${e}${e}${o}${e}${e}${o}${o}${e}${e}${o}${e}${attribute}")
    set(cut "")
    if (MAKE_FILE_KIND STREQUAL "stl-cut")
      set(cut "${e}${e}${e}${e}${e}")
    endif ()
    file(WRITE "${MAKE_FILE}" "${header}${first}${second}${cut}")
  elseif (MAKE_FILE_KIND STREQUAL "face-color-ply")
    file(WRITE "${MAKE_FILE}"
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 255 0 0\n3 0 2 3 0 255 0\n")
  elseif (MAKE_FILE_KIND STREQUAL "folder")
    file(REMOVE_RECURSE "${MAKE_FILE}")
    file(MAKE_DIRECTORY "${MAKE_FILE}")
  elseif (MAKE_FILE_KIND STREQUAL "link-dev-full")
    file(REMOVE "${MAKE_FILE}")
    file(CREATE_LINK /dev/full "${MAKE_FILE}" SYMBOLIC)
  elseif (MAKE_FILE_KIND STREQUAL "string-array-vtk")
    file(WRITE "${MAKE_FILE}"
      "# vtk DataFile Version 3.0\ntext labels\nASCII\nDATASET POLYDATA\n"
      "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 2 8\n3 0 1 2\n3 0 2 3\n"
      "POINT_DATA 4\nFIELD FieldData 1\nLabels 1 4 string\na\nb\nc\nd\n")
  elseif (MAKE_FILE_KIND STREQUAL "ply-extras")
    file(WRITE "${MAKE_FILE}"
      "ply\r\nformat ascii 1.0\r\ncomment made by a test\r\nobj_info nothing\r\n"
      "element vertex 4\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n"
      "element face 2\r\nproperty  list uint8 int32 vertex_indices\r\n"
      "element material 1\r\nproperty float diffuse_red\r\nproperty float diffuse_green\r\n"
      "property float diffuse_blue\r\nend_header\r\n"
      "0 0 0 255 0 0\r\n1 0 0  0 255 0\r\n1 1 0 0 0 255\r\n0 1 0 9 9 9\r\n"
      "3 0 1 2\r\n3 0 2 3\r\n0.5 0.5 0.5\r\n")
  elseif (MAKE_FILE_KIND MATCHES "^ply-(no-index-list|long-face)$")
    set(list "property list uchar int vertex_indices")
    set(face "3 0 1 2")
    if (MAKE_FILE_KIND STREQUAL "ply-no-index-list")
      set(list "property list uchar int corners")
    else ()
      set(list "property list int int vertex_indices")
      set(face "300")
      foreach (k RANGE 299)
        math(EXPR corner "${k} % 3")
        string(APPEND face " ${corner}")
      endforeach ()
    endif ()
    file(WRITE "${MAKE_FILE}"
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\n${list}\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n${face}\n")
  elseif (MAKE_FILE_KIND STREQUAL "strip")
    file(WRITE "${MAKE_FILE}"
      "# vtk DataFile Version 3.0\none strip\nASCII\nDATASET POLYDATA\n"
      "POINTS 8 float\n0 0 0 0 1 0 1 0 0 1 1 0 2 0 0 2 1 0 3 0 0 3 1 0\n"
      "TRIANGLE_STRIPS 1 9\n8 0 1 2 3 4 5 6 7\n")
  elseif (MAKE_FILE_KIND STREQUAL "truncated")
    file(COPY_FILE "${MAKE_FILE_FROM}" "${MAKE_FILE}")
    execute_process(COMMAND truncate -s "${MAKE_FILE_SIZE}" "${MAKE_FILE}" RESULT_VARIABLE cut)
    if (NOT cut EQUAL 0)
      check_failed("RunCheck.cmake: truncate failed")
    endif ()
  else ()
    check_failed("RunCheck.cmake: unknown MAKE_FILE_KIND '${MAKE_FILE_KIND}'")
  endif ()
endif ()

if (DEFINED CHECK_FILE_ABSENT)
  file(REMOVE "${CHECK_FILE_ABSENT}")
endif ()
foreach (fresh IN LISTS FRESH)
  file(REMOVE "${fresh}")
endforeach ()
if (DEFINED CHECK_FILE AND NOT CHECK_FILE STREQUAL "${MAKE_FILE}")
  file(REMOVE "${CHECK_FILE}")
endif ()
execute_process(COMMAND ${command}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
set(all "${out}${err}")
message(STATUS "command: ${command}\nexit status: ${status}\n--- output ---\n${all}--------------")

if (EXPECT STREQUAL "success")
  if (NOT status STREQUAL "0")
    check_failed("expected success, got exit status '${status}'")
  endif ()
elseif (EXPECT STREQUAL "failure")
  if (status STREQUAL "0")
    check_failed("expected a failure, but the command succeeded")
  endif ()
  if (NOT status MATCHES "^[0-9]+$")
    check_failed("expected a clean non-zero exit, got '${status}' (a crash?)")
  endif ()
  if (DEFINED EXIT_CODE AND NOT status EQUAL EXIT_CODE)
    check_failed("expected exit status ${EXIT_CODE}, got ${status}")
  endif ()
else ()
  check_failed("RunCheck.cmake: EXPECT must be success or failure")
endif ()
if (DEFINED REGEX AND NOT all MATCHES "${REGEX}")
  check_failed("the output does not match '${REGEX}'")
endif ()
if (DEFINED FORBID AND all MATCHES "${FORBID}")
  check_failed("the output matches '${FORBID}', which it must not")
endif ()
# Whatever the command, a VTK message printed raw (by VTK's output window or logger, which the
# tools' own message catchers replace) is a message the tools failed to catch and word
# (ALLOW_RAW_VTK: not checked, for the check of this check).
if (NOT ALLOW_RAW_VTK AND all MATCHES "(ERROR|Warning): In [^\n]*, line [0-9]+|[ ](ERR|WARN)\\| ")
  check_failed("the output holds a raw VTK message: ${CMAKE_MATCH_0}")
endif ()
foreach (fresh IN LISTS FRESH)
  if (NOT EXISTS "${fresh}")
    check_failed("${fresh} was not written")
  endif ()
endforeach ()
if (DEFINED CHECK_FILE_ABSENT AND EXISTS "${CHECK_FILE_ABSENT}")
  check_failed("${CHECK_FILE_ABSENT} was written")
endif ()
if (DEFINED CHECK_FILE)
  if (NOT EXISTS "${CHECK_FILE}")
    check_failed("${CHECK_FILE} was not written")
  endif ()
  file(READ "${CHECK_FILE}" content)
  if (DEFINED CHECK_FILE_REGEX AND NOT content MATCHES "${CHECK_FILE_REGEX}")
    check_failed("${CHECK_FILE} does not match '${CHECK_FILE_REGEX}'")
  endif ()
endif ()
