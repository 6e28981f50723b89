"""procex meshes into Blender data: one Blender mesh from the parts of a
building (NumPy arrays straight into foreach_set) with procex's texture
coordinates (metres) as its UV map and procex's flat face normals as its
custom normals, one material per face tag and look (a Material node's or a
placed mesh's own .mtl: colour, roughness, metalness, texture image), placed meshes as linked duplicates (objects
sharing one mesh datablock)."""
import zlib

import bpy
from mathutils import Matrix
import numpy as np

PLACED_KEY = "procex_placed"  # marks the objects the add-on placed (replaced on re-evaluation)
UV_MAP = "UVMap"  # Blender's default name, which its texture nodes and exporters take first
LOOK_KEY = "procex_look"  # on a material: the look it was made for


def material(tag, own=None):
    """The material of a face tag, made once per look: its own (own:
    procex.Mesh.materials[tag], a Material node's or a placed mesh's .mtl) or
    a colour of the tag's own. Two looks of one tag (two placed meshes'
    "frame", or a look changed by re-evaluation) are two materials, the
    second named with Blender's .001 suffix."""
    name = "procex " + (tag or "untagged")
    look = repr(sorted(own.items())) if own is not None else "tag colour"
    for m in bpy.data.materials:
        if m.get(LOOK_KEY) == look and (m.name == name or m.name.startswith(name + ".")):
            return m
    m = bpy.data.materials.new(name)
    m[LOOK_KEY] = look
    if own is None:
        h = zlib.crc32(name.encode())
        m.diffuse_color = (0.35 + 0.6 * (h & 255) / 255, 0.35 + 0.6 * ((h >> 8) & 255) / 255,
                           0.35 + 0.6 * ((h >> 16) & 255) / 255, 1.0)
    else:
        _own_look(m, own)
    return m


def _own_look(m, own):
    """The look in a Principled BSDF: the colour as base colour, times the
    image (procex resolved its path, confined to the recipe's folder) seen
    through a Mapping node that scales the UVs (metres) by 1 / tile_size, and
    the roughness and metalness."""
    m.diffuse_color = (*own["colour"], 1.0)
    m.roughness = own["roughness"]
    m.metallic = own["metallic"]
    m.use_nodes = True
    nodes = m.node_tree.nodes
    bsdf = next(n for n in nodes if n.type == "BSDF_PRINCIPLED")
    bsdf.inputs["Base Color"].default_value = (*own["colour"], 1.0)
    bsdf.inputs["Roughness"].default_value = own["roughness"]
    bsdf.inputs["Metallic"].default_value = own["metallic"]
    if own["texture"] is None:
        return
    image = nodes.new("ShaderNodeTexImage")
    image.image = bpy.data.images.load(own["texture"], check_existing=True)
    if own["tile_size"] != 1.0:
        coords = nodes.new("ShaderNodeTexCoord")
        mapping = nodes.new("ShaderNodeMapping")
        mapping.vector_type = "POINT"
        mapping.inputs["Scale"].default_value = (1.0 / own["tile_size"], 1.0 / own["tile_size"], 1.0)
        m.node_tree.links.new(coords.outputs["UV"], mapping.inputs["Vector"])
        m.node_tree.links.new(mapping.outputs["Vector"], image.inputs["Vector"])
    colour = image.outputs["Color"]
    if own["colour"] != (1.0, 1.0, 1.0):  # the colour multiplies the image, as glTF's baseColorFactor does
        mix = nodes.new("ShaderNodeVectorMath")
        mix.operation = "MULTIPLY"
        mix.inputs[1].default_value = own["colour"]
        m.node_tree.links.new(colour, mix.inputs[0])
        colour = mix.outputs["Vector"]
    m.node_tree.links.new(colour, bsdf.inputs["Base Color"])


def fill(me, parts):
    """Replaces the geometry of Blender mesh me with the parts (procex.Mesh list), in place."""
    tags = []
    slot = {}
    vertices, starts, totals, indices, materials, edges, uvs, normals = [], [], [], [], [], [], [], []
    vertex_base = loop_base = 0
    for part in parts:
        offsets = part.face_offsets
        vertices.append(part.vertices)
        starts.append(offsets[:-1] + loop_base)
        totals.append(np.diff(offsets))
        uvs.append(part.uvs)
        normals.append(np.repeat(part.normals, totals[-1], axis=0))  # each face's, at each of its corners
        indices.append(part.face_indices + vertex_base)
        for t in part.tags:
            slot.setdefault(t, len(slot))
            if len(tags) < len(slot):
                tags.append(t)
        lut = np.array([slot[t] for t in part.tags], dtype=np.int32)
        materials.append(lut[part.face_tags] if len(lut) else np.zeros(part.n_faces, np.int32))
        edges.append(part.source_edges if len(part.source_edges) else np.full(part.n_faces, -1, np.int32))
        vertex_base += part.n_vertices
        loop_base += len(part.face_indices)
    cat = (lambda a, dtype: np.ascontiguousarray(np.concatenate(a), dtype=dtype) if a else np.zeros(0, dtype))
    co = cat(vertices, np.float32).ravel() if vertices else np.zeros(0, np.float32)
    loop_start, loop_total = cat(starts, np.int32), cat(totals, np.int32)
    me.clear_geometry()
    me.vertices.add(len(co) // 3)
    me.vertices.foreach_set("co", co)
    me.loops.add(loop_base)
    me.loops.foreach_set("vertex_index", cat(indices, np.int32))
    me.polygons.add(len(loop_start))
    me.polygons.foreach_set("loop_start", loop_start)
    me.polygons.foreach_set("loop_total", loop_total)
    # Slots first: clearing them resets every face's material index to 0.
    me.materials.clear()
    own = {}
    for part in parts:
        for t, look in part.materials.items():
            own.setdefault(t, look)
    for t in tags:
        me.materials.append(material(t, own.get(t)))
    me.polygons.foreach_set("material_index", cat(materials, np.int32))
    attribute = me.attributes.get("procex_source_edge") or me.attributes.new("procex_source_edge", "INT", "FACE")
    attribute.data.foreach_set("value", cat(edges, np.int32))
    me.uv_layers.new(name=UV_MAP, do_init=False).data.foreach_set("uv", cat(uvs, np.float32).ravel())
    me.update(calc_edges=True)
    # Each corner has its face's normal: flat shading. Before Blender 4.1 custom normals show only with auto smooth.
    if hasattr(me, "use_auto_smooth"):
        me.use_auto_smooth = True
    me.normals_split_custom_set(cat(normals, np.float32).reshape(-1, 3))
    return me


def place(obj, parts, shared=None):
    """Replaces the objects placed on obj by the parts' placed meshes: one
    child object per placement, sharing one Blender mesh per distinct procex
    mesh (across calls too when `shared` is the same dict)."""
    for child in [c for c in obj.children if c.get(PLACED_KEY)]:
        bpy.data.objects.remove(child)
    shared = {} if shared is None else shared
    collections = obj.users_collection or (bpy.context.scene.collection,)
    count = 0
    for part in parts:
        for placement in part.placed:
            mesh, matrix = placement
            # one procex mesh under one name (its untagged faces take the name), however many placements
            key = (mesh.vertices.__array_interface__["data"][0], mesh.name)
            data = shared.get(key)
            if data is None:
                data = shared[key] = fill(bpy.data.meshes.new(mesh.name or "placed"), [mesh])
            child = bpy.data.objects.new(f"{obj.name} {data.name} {count}", data)
            child[PLACED_KEY] = True
            child.parent = obj
            child.matrix_basis = Matrix(matrix.tolist())
            if placement.tag:  # the placement's tag wins over the mesh's own
                for i, s in enumerate(child.material_slots):
                    s.link = "OBJECT"
                    child.material_slots[i].material = material(placement.tag)
            for c in collections:
                c.objects.link(child)
            count += 1
    return count
