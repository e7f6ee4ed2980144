#!/usr/bin/env python3
"""Writes an OBJ file as a POV-Ray mesh2 (for the POV-Ray twins of scenes with meshes).

Faces are fanned into triangles as raylab's loader fans them; z is mirrored (vertices and
normals) for POV-Ray's left-handed coordinates, so the object's transform is the raylab
one with rotations about x and y negated and z translations mirrored.
usage: obj_mesh2.py FILE.obj TEXTURE_NAME > part.pov
"""
import sys


def index(token, count):
    """A 1-based or negative (relative) OBJ index as a 0-based one."""
    i = int(token)
    return i - 1 if i > 0 else count + i


path, texture = sys.argv[1], sys.argv[2]
vertices, normals, faces = [], [], []
for line in open(path):
    parts = line.split()
    if not parts:
        continue
    if parts[0] == "v":
        x, y, z = map(float, parts[1:4])
        vertices.append((x, y, -z))
    elif parts[0] == "vn":
        x, y, z = map(float, parts[1:4])
        normals.append((x, y, -z))
    elif parts[0] == "f":
        corners = []
        for corner in parts[1:]:
            fields = corner.split("/")
            v = index(fields[0], len(vertices))
            n = index(fields[2], len(normals)) if len(fields) > 2 and fields[2] else None
            corners.append((v, n))
        for k in range(1, len(corners) - 1):
            faces.append((corners[0], corners[k], corners[k + 1]))

smooth = normals and all(n is not None for face in faces for _, n in face)
print("mesh2 {")
print(f"  vertex_vectors {{ {len(vertices)},")
print(",\n".join(f"    <{x:.6f}, {y:.6f}, {z:.6f}>" for x, y, z in vertices))
print("  }")
if smooth:
    print(f"  normal_vectors {{ {len(normals)},")
    print(",\n".join(f"    <{x:.6f}, {y:.6f}, {z:.6f}>" for x, y, z in normals))
    print("  }")
print(f"  face_indices {{ {len(faces)},")
print(",\n".join(f"    <{a[0]}, {b[0]}, {c[0]}>" for a, b, c in faces))
print("  }")
if smooth:
    print(f"  normal_indices {{ {len(faces)},")
    print(",\n".join(f"    <{a[1]}, {b[1]}, {c[1]}>" for a, b, c in faces))
    print("  }")
print(f"  texture {{ {texture} }}")
print("}")
