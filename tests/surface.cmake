# Curved-surface stages: base preparation, conformal patches, guidance fields, cells and holes,
# linked from meshquilt_mesh and meshquilt_quilt. Real meshes come from ../shared when present.
meshquilt_test(base_mesh_test SOURCES base_mesh_test.cpp LIBS meshquilt_mesh)
meshquilt_test(conformal_patch_test SOURCES conformal_patch_test.cpp LIBS meshquilt_quilt meshquilt_mesh)
meshquilt_test(guidance_field_test SOURCES guidance_field_test.cpp LIBS meshquilt_quilt meshquilt_mesh)
meshquilt_test(surface_cells_test SOURCES surface_cells_test.cpp LIBS meshquilt_quilt meshquilt_mesh)
meshquilt_test(hole_tracker_test SOURCES hole_tracker_test.cpp LIBS meshquilt_quilt)
meshquilt_test(surface_quilting_test SOURCES surface_quilting_test.cpp
  LIBS meshquilt_shell meshquilt_quilt meshquilt_inspect meshquilt_swatch meshquilt_spatial meshquilt_mesh meshquilt_engine
  LABELS end_to_end)
meshquilt_test(element_placement_test SOURCES element_placement_test.cpp LIBS meshquilt_quilt meshquilt_spatial meshquilt_mesh)
