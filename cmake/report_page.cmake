# The pages' JavaScript (docs/report.md, "How the page is built"): the packages pinned in
# web/package-lock.json are installed with `npm ci` into the build folder (never into the source tree),
# each page's web/src/NAME/main.js is bundled by esbuild into ${CMAKE_BINARY_DIR}/web/NAME.{js,css}, and
# the bundle becomes a generated C++ source of shatter_harness (cmake/embed_report_bundle.cmake). Pages:
# the report (report.html) and the history dashboard (dashboard.html, docs/dashboard.md). Editing a
# file under web/src bundles again; editing package*.json installs again.
find_program(SHATTER_NODE node)
find_program(SHATTER_NPM npm)
if(NOT SHATTER_NODE OR NOT SHATTER_NPM)
  message(FATAL_ERROR "node and npm are needed to bundle the report page (web/): scripts/install-deps installs them")
endif()

set(SHATTER_WEB_DIR ${CMAKE_BINARY_DIR}/web)
file(MAKE_DIRECTORY ${SHATTER_WEB_DIR})
set(SHATTER_WEB_INSTALLED ${SHATTER_WEB_DIR}/node_modules/.shatter-npm-ci.stamp)
add_custom_command(
  OUTPUT ${SHATTER_WEB_INSTALLED}
  COMMAND ${CMAKE_COMMAND} -E copy ${PROJECT_SOURCE_DIR}/web/package.json ${PROJECT_SOURCE_DIR}/web/package-lock.json
          ${SHATTER_WEB_DIR}
  # --ignore-scripts: no package runs code at install; puppeteer-core downloads no browser in any case.
  COMMAND ${CMAKE_COMMAND} -E env PUPPETEER_SKIP_DOWNLOAD=1 ${SHATTER_NPM} ci --ignore-scripts --no-audit --no-fund
          --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${SHATTER_WEB_INSTALLED}
  WORKING_DIRECTORY ${SHATTER_WEB_DIR}
  DEPENDS ${PROJECT_SOURCE_DIR}/web/package.json ${PROJECT_SOURCE_DIR}/web/package-lock.json
  COMMENT "npm ci: the report page's pinned packages (web/package-lock.json) into ${SHATTER_WEB_DIR}"
  VERBATIM)

file(GLOB_RECURSE SHATTER_WEB_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/web/src/*.js
     ${PROJECT_SOURCE_DIR}/web/src/*.css)

# One page: web/src/${name}/main.js bundled into ${SHATTER_WEB_DIR}/${name}.{js,css} and compiled into
# shatter_harness as ${name}_script(), ${name}_style() and ${name}_licenses() (declared in `header`, a
# path from the source root), with the licences of `notices`; the target shatter_${name}_bundle runs it.
function(shatter_web_page name header notices)
  set(script ${SHATTER_WEB_DIR}/${name}.js)
  set(style ${SHATTER_WEB_DIR}/${name}.css)
  add_custom_command(
    OUTPUT ${script} ${style}
    # NODE_PATH: the sources import "uplot" from the build folder's node_modules.
    COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=${SHATTER_WEB_DIR}/node_modules
            ${SHATTER_NODE} ${SHATTER_WEB_DIR}/node_modules/esbuild/bin/esbuild
            ${PROJECT_SOURCE_DIR}/web/src/${name}/main.js --bundle --minify --format=iife --charset=ascii
            # The packages' licences go whole into the page's head comment (cmake/web_notices.cmake).
            --legal-comments=none
            --target=es2020 --outfile=${script} --log-level=warning
    DEPENDS ${SHATTER_WEB_INSTALLED} ${SHATTER_WEB_SOURCES}
    COMMENT "esbuild: the ${name} page's script and style (web/src/${name})"
    VERBATIM)
  set(source ${CMAKE_BINARY_DIR}/generated/${name}_bundle.cpp)
  add_custom_command(
    OUTPUT ${source}
    COMMAND ${CMAKE_COMMAND} -DNAME=${name} -DHEADER=${header} -DSCRIPT=${script} -DSTYLE=${style}
            -DLICENSES=${notices} -DOUT=${source} -P ${PROJECT_SOURCE_DIR}/cmake/embed_report_bundle.cmake
    DEPENDS ${script} ${style} ${notices} ${PROJECT_SOURCE_DIR}/cmake/embed_report_bundle.cmake
    COMMENT "Embedding the ${name} page's bundle in ${source}"
    VERBATIM)
  # One target runs the commands; shatter_harness waits for it (two targets sharing a custom command's
  # output could run it twice at once in a parallel make).
  add_custom_target(shatter_${name}_bundle DEPENDS ${source})
  target_sources(shatter_harness PRIVATE ${source})
  add_dependencies(shatter_harness shatter_${name}_bundle)
endfunction()

# The licence of every package the bundle holds goes into the page (uPlot's MIT licence asks for it).
set(SHATTER_WEB_BUNDLED_PACKAGES uplot three)
set(SHATTER_WEB_NOTICES ${SHATTER_WEB_DIR}/notices.txt)
add_custom_command(
  OUTPUT ${SHATTER_WEB_NOTICES}
  COMMAND ${CMAKE_COMMAND} -DNODE_MODULES=${SHATTER_WEB_DIR}/node_modules "-DPACKAGES=${SHATTER_WEB_BUNDLED_PACKAGES}"
          -DOUT=${SHATTER_WEB_NOTICES} -P ${PROJECT_SOURCE_DIR}/cmake/web_notices.cmake
  DEPENDS ${SHATTER_WEB_INSTALLED} ${PROJECT_SOURCE_DIR}/cmake/web_notices.cmake
  COMMENT "The licences of the report page's bundled packages"
  VERBATIM)

shatter_web_page(report harness/report/html/report_bundle.h ${SHATTER_WEB_NOTICES})

# The history dashboard bundles uPlot only.
set(SHATTER_DASHBOARD_NOTICES ${SHATTER_WEB_DIR}/dashboard-notices.txt)
add_custom_command(
  OUTPUT ${SHATTER_DASHBOARD_NOTICES}
  COMMAND ${CMAKE_COMMAND} -DNODE_MODULES=${SHATTER_WEB_DIR}/node_modules -DPACKAGES=uplot
          -DOUT=${SHATTER_DASHBOARD_NOTICES} -P ${PROJECT_SOURCE_DIR}/cmake/web_notices.cmake
  DEPENDS ${SHATTER_WEB_INSTALLED} ${PROJECT_SOURCE_DIR}/cmake/web_notices.cmake
  COMMENT "The licences of the dashboard's bundled packages"
  VERBATIM)
shatter_web_page(dashboard harness/history/dashboard/dashboard_bundle.h ${SHATTER_DASHBOARD_NOTICES})
