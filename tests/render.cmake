# Preview rendering: ray casting against brute force, camera framing in closed form, element
# colours, PNG encoding (libpng reads it back), and the `meshquilt render` command.
meshquilt_test(render_test NEEDS_CLI SOURCES render_test.cpp
  LIBS meshquilt_render meshquilt_spatial meshquilt_mesh PNG::PNG)
