add_executable(table1_runner ${CMAKE_CURRENT_LIST_DIR}/table1_runner.cpp)
target_link_libraries(table1_runner PRIVATE meshquilt_mesh glm::glm nlohmann_json::nlohmann_json)
target_compile_definitions(table1_runner PRIVATE MESHQUILT_CLI="$<TARGET_FILE:meshquilt>"
                                                   MESHQUILT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(table1_runner meshquilt)
