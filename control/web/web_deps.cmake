# The third-party files the web monitor embeds (control/web-deps, pinned by its
# package-lock.json; `npm ci` there, as scripts/setup.sh does, fills
# node_modules): uPlot's script and stylesheet for the trend plots. Sets
# WEB_DEPS_FILES for control/CMakeLists.txt. Checked at configure time so a
# checkout without them stops here with the fix, not in a 404 in the browser.
set(WEB_DEPS_DIR ${CMAKE_CURRENT_SOURCE_DIR}/web-deps)
# A packager without npm may point this at an unpacked uplot-<version>.tgz.
set(SLMP_UPLOT_DIR ${WEB_DEPS_DIR}/node_modules/uplot CACHE PATH
    "uPlot's npm package (its dist/ is embedded into slmp-sim)")
set(WEB_DEPS_FILES ${SLMP_UPLOT_DIR}/dist/uPlot.iife.min.js ${SLMP_UPLOT_DIR}/dist/uPlot.min.css)

set(fix "run scripts/setup.sh (or: cd ${WEB_DEPS_DIR} && npm ci)")
foreach(file IN LISTS WEB_DEPS_FILES ITEMS ${SLMP_UPLOT_DIR}/LICENSE)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "the web monitor embeds ${file}, which is missing; ${fix}")
  endif()
endforeach()
# uPlot is MIT-licensed: its notice travels with it, served as /uPlot.LICENSE.txt.
configure_file(${SLMP_UPLOT_DIR}/LICENSE ${CMAKE_CURRENT_BINARY_DIR}/uPlot.LICENSE.txt COPYONLY)
list(APPEND WEB_DEPS_FILES ${CMAKE_CURRENT_BINARY_DIR}/uPlot.LICENSE.txt)

# node_modules left from an older package-lock.json would embed the wrong
# version silently; the lock file names the one the monitor was written for.
file(READ ${WEB_DEPS_DIR}/package-lock.json lock)
string(JSON wanted GET "${lock}" packages node_modules/uplot version)
file(READ ${SLMP_UPLOT_DIR}/package.json installed_json)
string(JSON installed GET "${installed_json}" version)
if(NOT installed STREQUAL wanted)
  message(FATAL_ERROR "${SLMP_UPLOT_DIR} is uPlot ${installed}, but control/web-deps/package-lock.json pins ${wanted}; ${fix}")
endif()
# Reconfigure (and check again) when the lock file or the installed package changes.
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${WEB_DEPS_DIR}/package-lock.json ${SLMP_UPLOT_DIR}/package.json)
