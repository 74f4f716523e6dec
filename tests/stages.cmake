# Quilting stages: seed finding, element correspondences, element deformation, linked from
# meshquilt_quilt.
meshquilt_test(seed_finding_test SOURCES seed_finding_test.cpp LIBS meshquilt_quilt)
meshquilt_test(element_deformation_test SOURCES element_deformation_test.cpp LIBS meshquilt_quilt)
meshquilt_test(correspondence_test SOURCES correspondence_test.cpp LIBS meshquilt_quilt)
meshquilt_test(patch_step_test SOURCES patch_step_test.cpp LIBS meshquilt_quilt meshquilt_swatch meshquilt_engine)
