# The planar quality suite (issue 8): every swatch kind over a 4x4 plane, measured by inspect.
add_executable(quality_suite ${CMAKE_CURRENT_LIST_DIR}/quality_suite.cpp)
target_link_libraries(quality_suite PRIVATE meshquilt_inspect meshquilt_mesh nlohmann_json::nlohmann_json)
target_compile_definitions(quality_suite PRIVATE MESHQUILT_CLI="$<TARGET_FILE:meshquilt>")
add_dependencies(quality_suite meshquilt)
