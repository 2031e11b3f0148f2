# Writes the licence notices of the npm packages bundled into the report page, one after another:
#   cmake -DNODE_MODULES=dir "-DPACKAGES=uplot;..." -DOUT=notices.txt -P web_notices.cmake
# Each notice is "<name> <version>:" then the package's LICENSE file (its version from its package.json).
cmake_minimum_required(VERSION 3.22)
set(text "")
foreach(package IN LISTS PACKAGES)
  set(dir "${NODE_MODULES}/${package}")
  file(READ "${dir}/package.json" manifest)
  string(JSON version GET "${manifest}" version)
  file(GLOB license_files "${dir}/LICENSE" "${dir}/LICENSE.*" "${dir}/LICENCE" "${dir}/license")
  if(NOT license_files)
    message(FATAL_ERROR "web_notices.cmake: ${dir} has no LICENSE file")
  endif()
  list(GET license_files 0 license_file)
  file(READ "${license_file}" license)
  string(STRIP "${license}" license)
  # The page's bundle is ASCII: a licence's copyright sign becomes "(c)", any other byte past ASCII "?".
  string(REPLACE "©" "(c)" license "${license}")
  string(REGEX REPLACE "[^\t\n\r -~]" "?" license "${license}")
  string(APPEND text "${package} ${version}:\n\n${license}\n\n")
endforeach()
file(WRITE "${OUT}" "${text}")
