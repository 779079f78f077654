# Writes builtin_profiles.cpp: every config/profiles/*.json as a string, so the
# simulator runs with no files beside it. Called by config/CMakeLists.txt.
string(REPLACE "|" ";" FILES "${FILES}")
set(body "// Generated from config/profiles/*.json by embed_profiles.cmake; do not edit.\n")
string(APPEND body "#include \"config/builtin_profiles.hpp\"\n\nnamespace slmp::config {\n\n")
string(APPEND body "const std::vector<BuiltinProfile>& builtin_profiles() {\n    static const std::vector<BuiltinProfile> profiles = {\n")
foreach(file IN LISTS FILES)
  get_filename_component(name "${file}" NAME_WE)
  file(READ "${file}" text)
  string(APPEND body "        {\"${name}\", R\"slmp_profile(${text})slmp_profile\"},\n")
endforeach()
string(APPEND body "    };\n    return profiles;\n}\n\n}  // namespace slmp::config\n")
file(WRITE "${OUT}.tmp" "${body}")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
