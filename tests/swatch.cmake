# Swatch generators: chain mail, weave, fruit, nuts, height field; Netpbm and weave patterns; the
# `meshquilt swatch` command. OpenMesh is the independent reader of the written files.
meshquilt_test(swatch_generators_test SOURCES swatch_generators_test.cpp
  LIBS meshquilt_swatch meshquilt_mesh OpenMeshCore)
meshquilt_test(swatch_patterns_test SOURCES swatch_patterns_test.cpp LIBS meshquilt_swatch meshquilt_mesh)
meshquilt_test(swatch_cli_test SOURCES swatch_cli_test.cpp LIBS meshquilt_swatch meshquilt_mesh)
add_dependencies(swatch_cli_test meshquilt)
