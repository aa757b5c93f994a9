# Writes a page from web/page.html: PAGE (the output), and either SCRIPT_SRC (a script tag that
# loads it: the site) or SCRIPT_FILE (its text put inside the page: the single file).
#   cmake -DTEMPLATE=page.html -DPAGE=out.html [-DSCRIPT_SRC=frictionlab.js | -DSCRIPT_FILE=x.js] -P make_page.cmake
file(READ "${TEMPLATE}" page)
if(DEFINED SCRIPT_FILE)
  file(READ "${SCRIPT_FILE}" script)
  # "</script" inside the script would end the element early; emscripten's output has none,
  # but a lesson's text embedded in it might.
  string(REPLACE "</script" "<\\/script" script "${script}")
  set(tag "<script>\n${script}\n</script>")
else()
  set(tag "<script src=\"${SCRIPT_SRC}\"></script>")
endif()
string(REPLACE "@FRICTIONLAB_SCRIPT@" "${tag}" page "${page}")
file(WRITE "${PAGE}" "${page}")
