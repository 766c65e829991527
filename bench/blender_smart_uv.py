# Blender's Smart UV Project with its defaults (angle limit 66 degrees, no island margin), for
# bench/bench_atlas.cpp: blender -b --python blender_smart_uv.py -- in.obj out.obj
# Prints the operator's own time (SMART_UV_SECONDS); writes the mesh with its UVs as OBJ.
import sys
import time

import bpy

source, target = sys.argv[sys.argv.index("--") + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=source)
mesh = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = mesh
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
start = time.perf_counter()
bpy.ops.uv.smart_project()
seconds = time.perf_counter() - start
bpy.ops.object.mode_set(mode="OBJECT")
print("SMART_UV_SECONDS %.6f" % seconds)
bpy.ops.wm.obj_export(filepath=target, export_selected_objects=False, export_uv=True, export_normals=False,
                      export_materials=False, export_triangulated_mesh=True)
