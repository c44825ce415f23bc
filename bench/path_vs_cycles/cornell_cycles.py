"""Renders glint's Cornell box (scenes/features/cornell-box.yaml) with Blender's Cycles, inside
Blender:

    blender -b --factory-startup -noaudio --python-exit-code 1 -P cornell_cycles.py -- \\
        --scene cornell-box.json --out out.exr --width W --height H --spp N --seed S \\
        --max-depth D --threads T

The scene is built from the YAML file itself, given as JSON (run.py converts it, so that
Blender's Python needs nothing beyond its standard library): its polygons and triangles as one
mesh each, its materials as Cycles' diffuse BSDF of colour kd * color, the light's emission on
its front side only (glint's emission_sides: front), its camera (glint's y up becomes Blender's
z up: (x, y, z) -> (x, -z, y), which keeps the camera's right where it was). Cycles renders on
the CPU with N samples a pixel, no adaptive sampling and no denoising, paths of at most D
surfaces (D - 1 bounces), each pixel's samples over its own square (a box filter one pixel wide,
as glint's --filter box), and writes linear RGB as 32-bit OpenEXR. Prints "render seconds: T",
the time of the render alone (Blender's own start-up and scene building excluded).
"""

import argparse
import json
import sys
import time

import bpy


def to_blender(p):
    x, y, z = p
    return (x, -z, y)


def material(name, spec):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    kd, color = spec.get("kd", 1), spec.get("color", [1, 1, 1])
    diffuse.inputs["Color"].default_value = [kd * c for c in color] + [1]
    shader = diffuse.outputs["BSDF"]
    if "emission" in spec:
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = list(spec["emission"]) + [1]
        emission.inputs["Strength"].default_value = 1
        add = nodes.new("ShaderNodeAddShader")
        links.new(diffuse.outputs["BSDF"], add.inputs[0])
        links.new(emission.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
        if spec.get("emission_sides") == "front":
            # The back side reflects but does not emit.
            geometry = nodes.new("ShaderNodeNewGeometry")
            mix = nodes.new("ShaderNodeMixShader")
            links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
            links.new(add.outputs["Shader"], mix.inputs[1])
            links.new(diffuse.outputs["BSDF"], mix.inputs[2])
            shader = mix.outputs["Shader"]
    links.new(shader, out.inputs["Surface"])
    return mat


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    parser = argparse.ArgumentParser()
    parser.add_argument("--scene", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--width", type=int, default=400)
    parser.add_argument("--height", type=int, default=400)
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--max-depth", type=int, default=8)
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args(argv)
    with open(args.scene) as f:
        scene_spec = json.load(f)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    materials = {name: material(name, spec) for name, spec in scene_spec["materials"].items()}
    for i, obj in enumerate(scene_spec["objects"]):
        if obj["type"] not in ("polygon", "triangle"):
            raise SystemExit("only polygons and triangles are built, not " + obj["type"])
        vertices = [to_blender(v) for v in obj["vertices"]]
        mesh = bpy.data.meshes.new("object%d" % i)
        mesh.from_pydata(vertices, [], [list(range(len(vertices)))])
        mesh.materials.append(materials[obj["material"]])
        scene.collection.objects.link(bpy.data.objects.new("object%d" % i, mesh))

    cam_spec = scene_spec["camera"]
    camera = bpy.data.cameras.new("camera")
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = cam_spec["fov"] * 3.141592653589793 / 180
    camera.clip_start, camera.clip_end = 0.01, 1e6
    camera_object = bpy.data.objects.new("camera", camera)
    scene.collection.objects.link(camera_object)
    from mathutils import Vector
    eye, at = Vector(to_blender(cam_spec["from"])), Vector(to_blender(cam_spec["at"]))
    camera_object.location = eye
    camera_object.rotation_euler = (at - eye).to_track_quat("-Z", "Y").to_euler()
    scene.camera = camera_object

    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0
    scene.world = world

    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = args.spp
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = args.seed
    cycles.max_bounces = cycles.diffuse_bounces = args.max_depth - 1
    cycles.glossy_bounces = cycles.transmission_bounces = args.max_depth - 1
    cycles.caustics_reflective = cycles.caustics_refractive = True
    cycles.sample_clamp_direct = cycles.sample_clamp_indirect = 0
    cycles.pixel_filter_type, cycles.filter_width = "BOX", 1.0  # glint's --filter box
    scene.render.threads_mode = "FIXED" if args.threads else "AUTO"
    if args.threads:
        scene.render.threads = args.threads
    scene.render.resolution_x, scene.render.resolution_y = args.width, args.height
    scene.render.resolution_percentage = 100
    scene.render.use_persistent_data = False
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGB"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    scene.view_settings.view_transform = "Standard"
    scene.render.filepath = args.out

    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print("render seconds: %.4f" % (time.perf_counter() - start))


if __name__ == "__main__":
    main()
