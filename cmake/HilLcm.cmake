# Debian's LCM 1.3.1 ships no lcmConfig.cmake: find lcm-gen, the headers and
# liblcm by hand, and provide hil_lcm_types() that generates C++ and Java.
find_program(LCM_GEN lcm-gen REQUIRED)
find_path(LCM_INCLUDE_DIR lcm/lcm-cpp.hpp REQUIRED)
find_library(LCM_LIBRARY lcm REQUIRED)
find_file(LCM_JAR lcm.jar PATHS /usr/share/java /usr/local/share/java REQUIRED)

add_library(lcm::lcm UNKNOWN IMPORTED)
set_target_properties(lcm::lcm PROPERTIES
  IMPORTED_LOCATION "${LCM_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${LCM_INCLUDE_DIR}")

# hil_lcm_types(TARGET JAR_NAME FILES...)
#   TARGET      INTERFACE library with the generated C++ headers (c++11: the
#               c++98 default breaks `const double`).
#   JAR_NAME    a jar of the compiled Java classes, for lcm-spy (RIG-2).
# Each file holds one type whose name is the file's name (package hil).
function(hil_lcm_types target jar_name)
  find_package(Java 11 REQUIRED COMPONENTS Development)
  set(cpp_dir ${CMAKE_CURRENT_BINARY_DIR}/cpp)
  set(java_dir ${CMAKE_CURRENT_BINARY_DIR}/java)
  set(class_dir ${CMAKE_CURRENT_BINARY_DIR}/classes)
  set(headers)
  set(java_sources)
  foreach(lcm_file IN LISTS ARGN)
    get_filename_component(type_name ${lcm_file} NAME_WE)
    list(APPEND headers ${cpp_dir}/hil/${type_name}.hpp)
    list(APPEND java_sources ${java_dir}/hil/${type_name}.java)
  endforeach()
  add_custom_command(
    OUTPUT ${headers} ${java_sources}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${cpp_dir} ${java_dir}
    COMMAND ${LCM_GEN} --cpp --cpp-std=c++11 --cpp-hpath ${cpp_dir} ${ARGN}
    COMMAND ${LCM_GEN} --java --jpath ${java_dir} ${ARGN}
    DEPENDS ${ARGN}
    COMMENT "lcm-gen: C++ and Java for the hil types"
    VERBATIM)
  set(jar ${CMAKE_BINARY_DIR}/share/java/${jar_name})
  add_custom_command(
    OUTPUT ${jar}
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${class_dir}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${class_dir} ${CMAKE_BINARY_DIR}/share/java
    COMMAND ${Java_JAVAC_EXECUTABLE} -nowarn -source 8 -target 8 -cp ${LCM_JAR} -d ${class_dir} ${java_sources}
    COMMAND ${Java_JAR_EXECUTABLE} cf ${jar} -C ${class_dir} .
    DEPENDS ${java_sources}
    COMMENT "javac + jar: ${jar_name} for lcm-spy"
    VERBATIM)
  add_custom_target(${target}_gen ALL DEPENDS ${headers} ${jar})
  add_library(${target} INTERFACE)
  add_dependencies(${target} ${target}_gen)
  target_include_directories(${target} INTERFACE ${cpp_dir})
  target_link_libraries(${target} INTERFACE lcm::lcm)
  set(HIL_TYPES_JAR ${jar} PARENT_SCOPE)
endfunction()
