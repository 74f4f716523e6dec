# Element merging: graph cut, stitching, merge_elements, linked from meshquilt_quilt.
meshquilt_test(graph_cut_test SOURCES graph_cut_test.cpp LIBS meshquilt_quilt)
meshquilt_test(stitching_test SOURCES stitching_test.cpp LIBS meshquilt_quilt)
meshquilt_test(element_merging_test SOURCES element_merging_test.cpp LIBS meshquilt_quilt)
meshquilt_test(quilt_policies_test SOURCES quilt_policies_test.cpp LIBS meshquilt_quilt meshquilt_swatch meshquilt_spatial meshquilt_mesh)
meshquilt_test(abutting_elements_test SOURCES abutting_elements_test.cpp LIBS meshquilt_quilt meshquilt_mesh)
