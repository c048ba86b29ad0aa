#!/usr/bin/env python3
"""Writes the seed inputs of the glTF-loader and compile-driver fuzz targets (issue 13).

Usage: make_seeds.py  (writes into corpus/gltf and corpus/compile beside this script)
The seeds are Kiln's own: small scenes in data URIs (no file outside the input), the shapes the
loader must handle (indices, materials, textures, lights, cameras, hierarchies, GLB) and the
hostile shapes it must refuse; small shaders with keywords, includes and the shapes the
pre-checks and workers must handle. Fuzzer-found inputs are merged in with libFuzzer's -merge=1.
"""
import base64
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
GLTF = os.path.join(HERE, "corpus", "gltf")
COMPILE = os.path.join(HERE, "corpus", "compile")


def uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(data).decode()


def png_uri(w, h):
    rows = b""
    for y in range(h):
        rows += b"\0" + b"".join(bytes([x * 60 % 256, y * 60 % 256, 128, 255]) for x in range(w))
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")
    return "data:image/png;base64," + base64.b64encode(png).decode()


def triangle(**extra):
    pos = struct.pack("<9f", -1, 0, 0, 1, 0, 0, 0, 1, 0)
    nrm = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
    uv = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    idx = struct.pack("<3H", 0, 1, 2) + b"\0\0"
    data = pos + nrm + uv + idx
    g = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(data), "uri": uri(data)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 36},
            {"buffer": 0, "byteOffset": 72, "byteLength": 24},
            {"buffer": 0, "byteOffset": 96, "byteLength": 6},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [-1, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1,
                                                     "TEXCOORD_0": 2},
                                      "indices": 3, "material": 0}]}],
        "materials": [{"name": "m", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.2, 1],
                                                            "metallicFactor": 0.1}}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }
    g.update(extra)
    return g


def write(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def gltf_seeds():
    write(GLTF, "triangle.gltf", json.dumps(triangle()))
    t = triangle()
    t["images"] = [{"uri": png_uri(4, 4)}]
    t["samplers"] = [{"magFilter": 9728, "wrapS": 33071}]
    t["textures"] = [{"source": 0, "sampler": 0}]
    t["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    t["materials"][0]["normalTexture"] = {"index": 0, "scale": 0.5}
    t["materials"][0]["alphaMode"] = "MASK"
    write(GLTF, "textured.gltf", json.dumps(t))
    t = triangle()
    t["extensionsUsed"] = ["KHR_lights_punctual"]
    t["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "intensity": 3},
        {"type": "point", "color": [1, 0.5, 0.5], "intensity": 20, "range": 5},
        {"type": "spot", "intensity": 10, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
    ]}}
    t["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1,
                                                            "zfar": 100}},
                    {"type": "orthographic", "orthographic": {"xmag": 2, "ymag": 2, "znear": 0.1,
                                                              "zfar": 10}}]
    t["nodes"] = [
        {"mesh": 0, "children": [1, 2, 3], "rotation": [0, 0.38, 0, 0.92]},
        {"translation": [0, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"translation": [1, 1, 3], "camera": 0,
         "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1], "camera": 1,
         "extensions": {"KHR_lights_punctual": {"light": 2}}},
    ]
    write(GLTF, "lights_cameras.gltf", json.dumps(t))
    # Without indices, a VEC3 COLOR_0 of unsigned bytes (normalized), no scenes at all.
    t = triangle()
    col = bytes([255, 0, 0, 0, 255, 0, 0, 0, 255])
    pos = struct.pack("<9f", -1, 0, 0, 1, 0, 0, 0, 1, 0)
    t["buffers"] = [{"byteLength": 48, "uri": uri(pos + col + b"\0\0\0")}]
    t["bufferViews"] = [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36,
                                                          "byteLength": 9}]
    t["accessors"] = [t["accessors"][0], {"bufferView": 1, "componentType": 5121,
                                          "normalized": True, "count": 3, "type": "VEC3"}]
    t["meshes"] = [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}}]}]
    del t["scenes"], t["scene"]
    write(GLTF, "colors_no_indices.gltf", json.dumps(t))
    # GLB of the triangle: JSON chunk + BIN chunk.
    t = triangle()
    data = base64.b64decode(t["buffers"][0]["uri"].split(",")[1])
    del t["buffers"][0]["uri"]
    js = json.dumps(t).encode()
    js += b" " * (-len(js) % 4)
    data += b"\0" * (-len(data) % 4)
    glb = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(js) + 8 + len(data))
    glb += struct.pack("<I", len(js)) + b"JSON" + js + struct.pack("<I", len(data)) + b"BIN\0" + data
    write(GLTF, "triangle.glb", glb)
    # Hostile shapes (each once crashed, hung or allocated without bound).
    t = triangle()
    t["accessors"][0]["count"] = 6148914691236517206
    write(GLTF, "count_wraps.gltf", json.dumps(t))
    t = triangle()
    t["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 100000000
    write(GLTF, "color_index.gltf", json.dumps(t))
    t = triangle()
    t["nodes"] = [{"children": [i + 1, i + 1]} if i < 20 else {"mesh": 0} for i in range(21)]
    write(GLTF, "shared_children.gltf", json.dumps(t))
    t = triangle()
    t["nodes"] = [{"children": [1]}, {"mesh": 0, "children": [0]}]
    write(GLTF, "cycle.gltf", json.dumps(t))
    t = triangle()
    t["scene"] = 5
    write(GLTF, "bad_default_scene.gltf", json.dumps(t))
    text = json.dumps(triangle())
    write(GLTF, "deep_extras.gltf", text[0] + '"extras": ' + "[" * 200 + "]" * 200 + ", " + text[1:])
    t = triangle()
    t["buffers"][0]["uri"] = "missing.bin"
    write(GLTF, "external_buffer.gltf", json.dumps(t))


PASS = """Shader "Fuzz/{name}" {{
    Properties {{ _Color ("Color", Color) = (1,1,1,1) _MainTex ("Tex", 2D) = "white" {{}} }}
    SubShader {{
        Tags {{ "RenderType"="Opaque" }}
        Pass {{
            Tags {{ "LightMode"="ForwardBase" }}
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
{pragmas}
            #include "UnityCG.cginc"
            float4 _Color;
            sampler2D _MainTex;
            struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; }};
            v2f vert(appdata_base v) {{ v2f o; o.pos = UnityObjectToClipPos(v.vertex);
                                       o.uv = v.texcoord.xy; return o; }}
            float4 frag(v2f i) : SV_Target {{
{body}
            }}
            ENDCG
        }}
    }}
}}
"""


def compile_seeds():
    def shader(name, pragmas="", body="return tex2D(_MainTex, i.uv) * _Color;"):
        write(COMPILE, name + ".shader", PASS.format(name=name, pragmas=pragmas, body=body))
    shader("plain")
    shader("keywords", "            #pragma multi_compile _ RED BLUE\n"
                       "            #pragma shader_feature _ _GLOW",
           "float4 c = _Color;\n#ifdef RED\nc.r = 1;\n#endif\n#if defined(BLUE)\nc.b = 1;\n#endif\n"
           "#ifdef _GLOW\nc *= 2;\n#endif\nreturn c;")
    shader("fwdadd", "            #pragma multi_compile_fwdadd", "return _Color;")
    shader("macros", "", "#define SQ(x) ((x)*(x))\n#define L2(x) (SQ(x)+SQ(x))\nreturn L2(_Color);")
    shader("type_error", "", "float4 c = _Color.rgb; return c;")
    shader("missing_semicolon", "", "float4 c = _Color\nreturn c;")
    shader("infinity", "", "return min(_Color, 1.#INF);")
    shader("nesting", "", "return " + "(" * 300 + "_Color" + ")" * 300 + ";")
    shader("uniform_crash", "", "return 1; } sampler2D _T; float4 _T}}}_ST; float4 g() { return 0;")
    shader("macro_doubling", "",
           "".join("#define M%d(i) (M%d(i)+M%d(i))\n" % (k, k - 1, k - 1) for k in range(1, 24))
           .replace("M0(i)", "(i)") + "return M23(1);")
    write(COMPILE, "fixed_function.shader", """Shader "Fuzz/FixedFunction" {
    Properties { _Color ("Main Color", Color) = (1,1,1,1) _MainTex ("Base", 2D) = "white" {} }
    SubShader { Pass {
        Material { Diffuse [_Color] Ambient [_Color] }
        Lighting On
        SetTexture [_MainTex] { combine texture * primary DOUBLE }
    } }
}
""")
    write(COMPILE, "hlslprogram.shader", """Shader "Fuzz/Hlsl" {
    HLSLINCLUDE
    float4 _Tint;
    float4 Shade(float4 c) { return c * _Tint; }
    ENDHLSL
    SubShader { Pass {
        ZWrite Off Blend SrcAlpha OneMinusSrcAlpha Cull [_Cull]
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        float4x4 unity_ObjectToWorld; float4x4 unity_MatrixVP;
        float4 vert(float3 p : POSITION) : SV_POSITION {
            return mul(unity_MatrixVP, mul(unity_ObjectToWorld, float4(p, 1))); }
        float4 frag() : SV_Target { return Shade(float4(1, 1, 1, 0.5)); }
        ENDHLSL
    } }
}
""")


if __name__ == "__main__":
    gltf_seeds()
    compile_seeds()
