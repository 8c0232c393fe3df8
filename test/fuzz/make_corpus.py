#!/usr/bin/env python3
"""Writes the seed corpora under test/fuzz/corpus/<target>/: a few tiny valid inputs per fuzz
target (plus, committed separately, inputs that once crashed). Re-running it rewrites the seeds
named seed_*; other files in the corpus directories are left alone.

Usage: test/fuzz/make_corpus.py
"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

POINTS = [(0.1, 0.2, 0.9), (-0.3, 0.05, 1.1), (0.25, -0.4, 0.8)]

# segments.json as segment_scene writes it: support, planes, scores, boxes, a completion.
SEGMENTS_JSON = """{"input_points": 10,
 "support": {"plane":[0.0,0.0,1.0,-0.7],"polygon":[[0.1,0.2,0.7],[0.9,0.2,0.7],[0.5,0.8,0.7]],"noise":0.0013},
 "segments": [
  {"indices":[0,3,9],"symmetry":{"normal":[0.0,1.0,0.0],"distance":-0.12},"scores":{"occlusion":0.98,"smoothness":0.01},"box":{"center":[0.42,0.31,0.76],"axes":[[0.8,0.6,0.0],[-0.6,0.8,0.0],[0.0,0.0,1.0]],"size":[0.2,0.1,0.12]},"completion":{"points":4,"box":{"center":[0.4,0.3,0.76],"axes":[[0.8,0.6,0.0],[-0.6,0.8,0.0],[0.0,0.0,1.0]],"size":[0.2,0.14,0.12]},"frame":{"position":[0.4,0.3,0.7],"orientation":[0.0,0.0,0.0,1.0]}}},
  {"indices":[1,2]}],
 "timing_ms": {"load":1.5,"total":40.1},
 "counts": {"segments":2}}
"""


def write(target, name, data):
    directory = os.path.join(HERE, "corpus", target)
    os.makedirs(directory, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(directory, "seed_" + name), "wb") as out:
        out.write(data)


def lzf_literals(data):
    """LZF stream made of literal runs only (control byte n < 32: n + 1 literal bytes)."""
    out = bytearray()
    for start in range(0, len(data), 32):
        chunk = data[start:start + 32]
        out.append(len(chunk) - 1)
        out += chunk
    return bytes(out)


def pcd_header(fields, sizes, types, points, data, width=None, height=1):
    width = points if width is None else width
    return ("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
            f"FIELDS {' '.join(fields)}\nSIZE {' '.join(map(str, sizes))}\nTYPE {' '.join(types)}\n"
            f"COUNT {' '.join('1' for _ in fields)}\nWIDTH {width}\nHEIGHT {height}\n"
            f"VIEWPOINT 0 0 1.5 1 0 0 0\nPOINTS {points}\nDATA {data}\n")


def pcd_seeds():
    xyz = ["x", "y", "z"]
    text = pcd_header(xyz, [4] * 3, ["F"] * 3, 3, "ascii")
    text += "".join(f"{x} {y} {z}\n" for x, y, z in POINTS)
    write("pcd_file", "ascii_xyz.pcd", text)

    fields = xyz + ["normal_x", "normal_y", "normal_z", "rgb"]
    body = b"".join(struct.pack("<6fI", x, y, z, 0.0, 0.0, 1.0, 0x00ff8040) for x, y, z in POINTS)
    write("pcd_file", "binary_normals_rgb.pcd",
          pcd_header(fields, [4] * 7, ["F"] * 6 + ["U"], 3, "binary").encode() + body)

    # binary_compressed stores each field's values together (all x, then all y, ...).
    columns = b"".join(struct.pack("<3f", *(p[i] for p in POINTS)) for i in range(3))
    packed = lzf_literals(columns)
    write("pcd_file", "compressed_xyz.pcd",
          pcd_header(xyz, [4] * 3, ["F"] * 3, 3, "binary_compressed").encode() +
          struct.pack("<II", len(packed), len(columns)) + packed)

    # Organised 2 x 2 with a NaN point and a double field.
    text = pcd_header(xyz + ["intensity"], [8, 8, 8, 2], ["F", "F", "F", "U"], 4, "ascii", width=2, height=2)
    text += "0 0 1 7\nnan nan nan 0\n0.5 0 1 3\n0 0.5 1 65535\n"
    write("pcd_file", "organised_double.pcd", text)


def ply_header(fmt, vertex_properties, count, extra=""):
    props = "".join(f"property {t} {n}\n" for t, n in vertex_properties)
    return (f"ply\nformat {fmt} 1.0\ncomment fuzz seed\nelement vertex {count}\n{props}{extra}end_header\n")


CAMERA_PROPERTIES = ["view_px", "view_py", "view_pz", "x_axisx", "x_axisy", "x_axisz", "y_axisx", "y_axisy",
                     "y_axisz", "z_axisx", "z_axisy", "z_axisz", "focal", "scalex", "scaley", "centerx",
                     "centery"]


def ply_seeds():
    xyz = [("float", "x"), ("float", "y"), ("float", "z")]
    text = ply_header("ascii", xyz, 3) + "".join(f"{x} {y} {z}\n" for x, y, z in POINTS)
    write("ply_file", "ascii_xyz.ply", text)

    props = xyz + [("float", "nx"), ("float", "ny"), ("float", "nz"),
                   ("uchar", "red"), ("uchar", "green"), ("uchar", "blue")]
    for fmt, order in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
        body = b"".join(struct.pack(order + "6f3B", x, y, z, 0.0, 0.0, 1.0, 200, 100, 50) for x, y, z in POINTS)
        write("ply_file", f"{fmt}_normals_rgb.ply", ply_header(fmt, props, 3).encode() + body)

    camera = "element camera 1\n" + "".join(f"property float {name}\n" for name in CAMERA_PROPERTIES)
    values = [0.0, 0.0, 1.5, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 0, 0]
    text = ply_header("ascii", xyz, 3, camera) + "".join(f"{x} {y} {z}\n" for x, y, z in POINTS)
    text += " ".join(str(v) for v in values) + "\n"
    write("ply_file", "ascii_camera.ply", text)

    faces = "element face 1\nproperty list uchar int vertex_indices\n"
    text = ply_header("ascii", xyz + [("double", "curvature")], 3, faces)
    text += "".join(f"{x} {y} {z} 0.5\n" for x, y, z in POINTS) + "3 0 1 2\n"
    write("ply_file", "ascii_face_list.ply", text)


# .bt: 2 bytes per inner node, 2 bits per child: 01 free leaf, 10 occupied leaf, 11 inner node.
BT_ONE_LEAF = bytes([0b10, 0])                               # root, child 0 occupied: 2 nodes
BT_TWO_LEVELS = bytes([0b11, 0b01000000]) + bytes([0b0110, 0])  # root: child 0 inner, child 7 free
# .ot: per node float log-odds then one byte of child bits, children in order.
OT_TWO_NODES = struct.pack("<fB", 0.85, 1) + struct.pack("<fB", 0.85, 0)
OT_COLOR_TWO_NODES = struct.pack("<f3BB", 0.85, 10, 20, 30, 1) + struct.pack("<f3BB", 0.85, 200, 0, 0, 0)


def octomap_file_seeds():
    def bt(size, data):
        return f"# Octomap OcTree binary file\nid OcTree\nsize {size}\nres 0.01\ndata\n".encode() + data

    def ot(size, data):
        return f"# Octomap OcTree file\nid OcTree\nsize {size}\nres 0.02\ndata\n".encode() + data

    write("octomap_file", "one_leaf.bt", bt(2, BT_ONE_LEAF))
    write("octomap_file", "two_levels.bt", bt(5, BT_TWO_LEVELS))
    write("octomap_file", "two_nodes.ot", ot(2, OT_TWO_NODES))
    write("octomap_file", "empty.ot", "# Octomap OcTree file\n# a comment\nid OcTree\nsize 0\nres 0.05\ndata\n")


def octomap_message_seeds():
    # flags (bit 0 binary), id index (0 OcTree, 1 ColorOcTree), resolution, data
    def message(binary, tree_id, resolution, data):
        return bytes([1 if binary else 0, tree_id]) + struct.pack("<d", resolution) + data

    write("octomap_message", "binary_octree", message(True, 0, 0.02, BT_TWO_LEVELS))
    write("octomap_message", "binary_color", message(True, 1, 0.05, BT_ONE_LEAF))
    write("octomap_message", "full_octree", message(False, 0, 0.02, OT_TWO_NODES))
    write("octomap_message", "full_color", message(False, 1, 0.02, OT_COLOR_TWO_NODES))


def cloud_message(height, width, fields, point_step, data, row_step=None, bigendian=False):
    """fields: (name index, offset, datatype, count); names as in fuzz_pointcloud2.cpp."""
    row_step = width * point_step if row_step is None else row_step
    out = struct.pack("<IIII", height, width, point_step, row_step) + bytes([1 if bigendian else 0, len(fields)])
    for name, offset, datatype, count in fields:
        out += struct.pack("<BIBI", name, offset, datatype, count)
    return out + data


FLOAT32 = 7


def pointcloud2_seeds():
    xyz = [(0, 0, FLOAT32, 1), (1, 4, FLOAT32, 1), (2, 8, FLOAT32, 1)]
    data = b"".join(struct.pack("<3f", *p) for p in POINTS)
    write("pointcloud2", "xyz", cloud_message(1, 3, xyz, 12, data))

    # x y z pad, normals pad, rgb: the layout PCL gives PointXYZRGBNormal-like clouds.
    fields = xyz + [(3, 16, FLOAT32, 1), (4, 20, FLOAT32, 1), (5, 24, FLOAT32, 1), (6, 32, FLOAT32, 1),
                    (8, 36, FLOAT32, 1)]
    data = b"".join(struct.pack("<4f4fff", x, y, z, 0, 0, 0, 1, 0, struct.unpack("<f", bytes([50, 100, 200, 0]))[0], 0.1)
                    for x, y, z in POINTS)
    write("pointcloud2", "xyz_normals_rgb", cloud_message(1, 3, fields, 40, data))

    # Organised 2 x 2, with row padding and a NaN point.
    nan = float("nan")
    rows = [struct.pack("<3f3f", 0, 0, 1, nan, nan, nan) + b"\0" * 4, struct.pack("<3f3f", 0.5, 0, 1, 0, 0.5, 1) + b"\0" * 4]
    write("pointcloud2", "organised_padded", cloud_message(2, 2, xyz, 12, b"".join(rows), row_step=28))


def side_file_seeds():
    write("labels_file", "three", bytes([3]) + b"0\n1\n1\n")
    write("labels_file", "one_line", bytes([4]) + b"0 2 2 7")
    write("plane_file", "table", "0 0 1 -0.72\n")
    write("plane_file", "tilted", "0.1 -0.2 3.5e0 1e-3")
    write("scene_info", "full", "kind: cluttered\nseed: 42\nsensor_origins:\n  - [0, 0, 1.2]\n  - [0.5, -0.5, 1]\n")
    write("scene_info", "kind_only", "kind: stacked-boxes_2\n")
    write("scene_info", "up", "kind: clutter\nup: [0, -0.8, -0.6]\nsensor_origins:\n  - [0, 0, 0]\n")
    write("segments_json", "with_box", SEGMENTS_JSON)
    write("segments_json", "plain", '{"input_points": 3, "segments": [{"indices": [0, 2]}], "timing_ms": {"total": 1}}\n')


if __name__ == "__main__":
    pcd_seeds()
    ply_seeds()
    octomap_file_seeds()
    octomap_message_seeds()
    pointcloud2_seeds()
    side_file_seeds()
