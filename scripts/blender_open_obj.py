# Opens an OBJ (+ MTL + texture) in Blender headless and prints what Blender sees: faces, UV layers
# and the textures its materials use. For scripts/main.sh:
#   blender -b --python scripts/blender_open_obj.py -- mesh.obj
import sys

import bpy

source = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=source)
mesh = bpy.context.selected_objects[0].data
textures = [
    "%s (%dx%d)" % (node.image.filepath, node.image.size[0], node.image.size[1])
    for material in mesh.materials if material and material.node_tree
    for node in material.node_tree.nodes if node.type == "TEX_IMAGE" and node.image
]
print("BLENDER_OPENED %d faces, %d UV layer(s), textures: %s" %
      (len(mesh.polygons), len(mesh.uv_layers), ", ".join(textures) or "none"))
