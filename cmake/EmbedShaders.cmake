# Turns each shader file into a C++ raw string so the library works without its data files;
# a file of the same name on the OSG data path still overrides it at run time (see Shaders.cpp).
# Usage: cmake -DOUT=file.cpp -DFILES="a|b" -P EmbedShaders.cmake
string(REPLACE "|" ";" FILES "${FILES}")
set(body "// generated from shaders/ by cmake/EmbedShaders.cmake; do not edit\n#include <map>\n#include <string>\nnamespace osgWater { namespace detail {\nconst std::map<std::string, std::string>& embeddedShaders()\n{\n    static const std::map<std::string, std::string> table = {\n")
foreach(f ${FILES})
  file(READ ${f} text)
  get_filename_component(name ${f} NAME)
  string(APPEND body "        {\"${name}\", R\"osgwater(${text})osgwater\"},\n")
endforeach()
string(APPEND body "    };\n    return table;\n}\n} }\n")
file(WRITE ${OUT}.tmp "${body}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.tmp ${OUT})
