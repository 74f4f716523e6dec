# Mesh foundation: I/O (OpenMesh is the independent reference reader), validation, topology and
# the swatch frame.
meshquilt_test(mesh_io_test SOURCES mesh_io_test.cpp LIBS meshquilt_mesh OpenMeshCore)
meshquilt_test(mesh_io_perf_test SOURCES mesh_io_perf_test.cpp LIBS meshquilt_mesh LABELS slow)
meshquilt_test(mesh_validation_test SOURCES mesh_validation_test.cpp LIBS meshquilt_mesh)
meshquilt_test(topology_test SOURCES topology_test.cpp LIBS meshquilt_mesh)
meshquilt_test(measures_test SOURCES measures_test.cpp LIBS meshquilt_mesh)
meshquilt_test(swatch_frame_test SOURCES swatch_frame_test.cpp LIBS meshquilt_mesh)
