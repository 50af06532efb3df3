# cmake -DROOT=<source dir> -P include_direction.cmake
# Fails when a library's sources include a folder above it in the dependency order, or when the
# halves inside gppl/ (compile, run, builtins) and prp/ (params, filters) reach into each other
# (docs/architecture.md): each folder lists the include prefixes it must not use.
set(rules
  "toolpath|gppl/ prp/ machines/ postproc/ bench/ tests/"
  "gppl|toolpath/ prp/ machines/ postproc/ bench/ tests/"
  "prp|gppl/ machines/ postproc/ bench/ tests/"
  "gppl/compile|gppl/run/"
  "gppl/run|gppl/compile/"
  "gppl/builtins|gppl/compile/ gppl/run/"
  "prp/params|prp/filters/"
  "machines|gppl/ prp/ postproc/ bench/ tests/"
  "machines/pikocnc|machines/2xaxiscnc/ machines/registry/registry"
  "machines/pikocnc/model|machines/pikocnc/script/"
  "machines/pikocnc/script|machines/pikocnc/model/"
  "machines/2xaxiscnc|machines/pikocnc/ machines/registry/registry"
  "machines/sinumerik|machines/2xaxiscnc/ machines/iso/ machines/pikocnc/ machines/registry/registry"
  "machines/iso|machines/2xaxiscnc/ machines/sinumerik/ machines/pikocnc/ machines/registry/registry"
  "machines/ncmodel|machines/pikocnc/ machines/2xaxiscnc/ machines/sinumerik/ machines/iso/ machines/registry/"
  "postproc/engine|machines/ postproc/checks/ postproc/cli/ bench/ tests/"
  "postproc/checks|postproc/cli/ bench/ tests/"
  "postproc/cli|bench/ tests/"
  "lsp|postproc/cli/ machines/ bench/ tests/"
)
set(violations "")
set(scanned 0)
foreach(rule IN LISTS rules)
  string(REPLACE "|" ";" parts "${rule}")
  list(GET parts 0 folder)
  list(GET parts 1 forbidden)
  string(REPLACE " " ";" forbidden "${forbidden}")
  file(GLOB_RECURSE sources "${ROOT}/${folder}/*.cpp" "${ROOT}/${folder}/*.hpp" "${ROOT}/${folder}/*.inc")
  if(NOT sources)
    message(FATAL_ERROR "no sources under ${ROOT}/${folder}: is ROOT right?")
  endif()
  foreach(source IN LISTS sources)
    math(EXPR scanned "${scanned} + 1")
    file(STRINGS "${source}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line IN LISTS includes)
      foreach(prefix IN LISTS forbidden)
        if(line MATCHES "include[ \t]*[\"<]${prefix}")
          file(RELATIVE_PATH rel "${ROOT}" "${source}")
          string(STRIP "${line}" line)
          list(APPEND violations "${rel}: ${line} (${folder}/ must not include ${prefix})")
        endif()
      endforeach()
    endforeach()
  endforeach()
endforeach()
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "includes against the dependency direction:\n  ${text}")
endif()
message(STATUS "include direction ok (${scanned} files)")
