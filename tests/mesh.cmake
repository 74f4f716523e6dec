# Mesh foundation: I/O (OpenMesh is the independent reference reader), validation, topology and
# the swatch frame.
meshquilt_test(mesh_io_test SOURCES mesh_io_test.cpp LIBS meshquilt_mesh OpenMeshCore)
