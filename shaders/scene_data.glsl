// scene_data.glsl — the scene as std140 blocks, twin of include/marchbox/gl/gpu_scene.h.

struct Object {
    vec4 posBound;   // centre xyz, bounding-sphere radius
    vec4 sizeMinor;  // box half-extents xyz, torus tube radius
    vec4 shape;      // radius, height, blend, unused
    ivec4 info;      // type, op, material, unused
    vec4 detail;     // cone's top radius, edge radius (round), wall thickness (shell), unused
    mat3 toLocal;    // world -> local rotation
};
#if NUM_GROUPS > 0
// A group of the compiled tree (src/gl/scene_compiler.cpp): its frame and bounds in the world.
struct Group {
    vec4 posBound;   // origin xyz, radius of a sphere about it that holds its shape, every copy
    vec4 spacing;    // between copies xyz; w: radius of a sphere that holds one copy's shape
    vec4 blend;      // x: smooth-blend radius of its join; yzw unused
    mat3 toLocal;    // world -> group frame rotation
};
#endif
struct Material {
    vec4 color;      // rgb, Kr
    vec4 coeffs;     // Ka, Kd, Ks, C
};
struct Light {
    vec4 vec;        // point: position; directional: unit vector towards the light
    vec4 color;      // rgb * intensity
};

#if OBJECTS_IN_STORAGE
layout(std430) readonly buffer ObjectStore { Object uObjects[]; };
#else
layout(std140) uniform Objects { Object uObjects[NUM_OBJECTS > 0 ? NUM_OBJECTS : 1]; };
#endif
#if NUM_GROUPS > 0 && OBJECTS_IN_STORAGE
layout(std430) readonly buffer GroupStore { Group uGroups[]; };
#elif NUM_GROUPS > 0
layout(std140) uniform Groups { Group uGroups[NUM_GROUPS]; };
#endif
layout(std140) uniform Materials { Material uMaterials[NUM_MATERIALS > 0 ? NUM_MATERIALS : 1]; };
layout(std140) uniform Lights { Light uLights[NUM_POINT_LIGHTS + NUM_DIR_LIGHTS > 0 ? NUM_POINT_LIGHTS + NUM_DIR_LIGHTS : 1]; };

#if USE_GRID
uniform usamplerBuffer uGridCells;  // cells + 1 offsets into uGridItems
uniform usamplerBuffer uGridItems;  // object indices, file order within a cell
uniform vec3 uGridOrigin;
uniform vec3 uGridCell;
uniform ivec3 uGridDims;
#endif
#if PLAIN == 2
uniform usamplerBuffer uPlainCells;  // the plain members' grid (intersect.glsl), as above
uniform usamplerBuffer uPlainItems;
uniform samplerBuffer uPlainShapes;  // three texels an object
uniform vec3 uPlainOrigin;
uniform vec3 uPlainCell;
uniform ivec3 uPlainDims;
#endif

uniform vec3 uCamPos;
uniform vec3 uCamRight;     // scaled by tan(fov/2)
uniform vec3 uCamUp;        // scaled by tan(fov/2)
uniform vec3 uCamForward;
uniform vec2 uResolution;      // the whole image, in pixels
uniform vec2 uSubpixel;        // this pass's sample position inside the pixel, 0..1
uniform float uSampleWeight;   // 1 / samples: the passes add up in the accumulation target
uniform float uEpsilon;
uniform float uPixelRadius;  // half a pixel's footprint per metre along a primary ray
uniform float uSampleRadius; // and half a supersample's: uPixelRadius / aa
uniform float uMaxDist;
uniform vec3 uBoundLo, uBoundHi;  // a box holding every object's reach (objectBounds)
uniform vec3 uRestLo, uRestHi;    // the same for the marched objects: all but the plain members
uniform vec3 uPlainLo, uPlainHi;  // and for the plain members (intersect.glsl)
uniform float uFloor;
uniform float uFog;
uniform vec3 uSkyTint;      // the brightest light's colour, largest channel 1
uniform float uSoftness;    // soft-shadow sharpness k: larger is harder

#if UBER
uniform int uObjectCount, uPointLights, uDirLights, uSteps, uShadows, uReflections;
uniform bool uGround, uAo, uUseGrid;
#define OBJECT_COUNT uObjectCount
#define POINT_LIGHTS uPointLights
#define DIR_LIGHTS uDirLights
#define GROUND_ON uGround
#else
#define OBJECT_COUNT NUM_OBJECTS
#define POINT_LIGHTS NUM_POINT_LIGHTS
#define DIR_LIGHTS NUM_DIR_LIGHTS
#define GROUND_ON bool(HAS_GROUND)
#endif
