#include "scene_renderer.h"

#include <GL/glcorearb.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "gl_program.h"

namespace weft::ui {
namespace {

// Surfaces: cloth (woven), obstacle (plain) and ground (grid), one program with a mode switch.
// Vertex layout: position (3), normal (3), material-space coordinates (2).
const char* kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aRest;
uniform mat4 uViewProjection;
out vec3 vPosition;
out vec3 vNormal;
out vec2 vRest;
void main() {
  vPosition = aPosition;
  vNormal = aNormal;
  vRest = aRest;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

const char* kSurfaceFragment = R"(#version 330 core
in vec3 vPosition;
in vec3 vNormal;
in vec2 vRest;
uniform int uMode;          // 0 cloth (woven), 1 obstacle (plain), 2 ground (grid)
uniform vec3 uTint;
uniform vec3 uLight;        // towards the light, normalized
uniform float uPitch;       // thread pitch (m)
uniform vec2 uWeft;         // weft direction in material space (cos, sin)
uniform float uBand;        // threads per yarn-dyed colour band
uniform int uPattern;       // 0 gingham, 1 plain, 2 flat (no threads: one colour)
uniform int uTinted;        // 1: the tear strength map below is drawn over the cloth
uniform sampler2D uStrength; // RGB the map's colour, A how much of it
uniform vec2 uStrengthLo;   // the map's material-space rectangle (m)
uniform vec2 uStrengthHi;
out vec4 outColour;

// Brightness across a thread: a rounded yarn, darker at its sides.
float yarn(float s) {
  float c = 2.0 * s - 1.0;
  return 0.45 + 0.55 * sqrt(max(1.0 - c * c, 0.0));
}

vec3 woven(vec2 rest) {
  if (uPattern == 2) return uTint * 0.81;  // the woven texture's mean brightness, without threads
  // Material space into the weft/warp frame: u along weft, v along warp, in threads.
  vec2 warp = vec2(-uWeft.y, uWeft.x);
  vec2 t = vec2(dot(rest, uWeft), dot(rest, warp)) / uPitch;
  vec2 cell = floor(t);
  vec2 f = t - cell;
  // Yarn-dyed bands of threads (a gingham check): every uBand threads the colour changes, so the
  // weft and warp directions stay readable from far away where single threads are sub-pixel.
  vec3 light = mix(uTint, vec3(0.96, 0.94, 0.88), 0.75);
  bool check = uPattern == 0;
  vec3 weftYarn = !check || mod(floor(cell.y / uBand), 2.0) < 0.5 ? uTint : light;  // weft threads: one per v row
  vec3 warpYarn = !check || mod(floor(cell.x / uBand), 2.0) < 0.5 ? uTint : light;  // warp threads: one per u column
  // Plain weave: weft over warp on one checker colour, under it on the other.
  bool weftOnTop = mod(cell.x + cell.y, 2.0) < 0.5;
  // The thread on top shows its round cross-section, and dips at the ends of its float.
  float across = weftOnTop ? f.y : f.x;
  float along = weftOnTop ? f.x : f.y;
  float shade = yarn(across) * (0.78 + 0.22 * sin(3.14159265 * along));
  vec3 colour = (weftOnTop ? weftYarn : warpYarn * 0.9) * shade;
  // Far away a thread is smaller than a pixel: fade to the mean so it does not alias.
  float footprint = max(fwidth(t.x), fwidth(t.y));
  vec3 mean = 0.5 * (weftYarn + 0.9 * warpYarn) * 0.81;
  return mix(colour, mean, smoothstep(0.35, 0.9, footprint));
}

vec3 ground(vec3 p) {
  vec2 g = p.xz / 0.25;  // a grid line every 25 cm
  vec2 w = fwidth(g);
  vec2 d = abs(fract(g - 0.5) - 0.5) / max(w, vec2(1e-6));
  float line = 1.0 - min(min(d.x, d.y), 1.0);
  line *= 1.0 - smoothstep(0.2, 0.6, max(w.x, w.y));  // lines denser than pixels fade out
  return mix(vec3(0.80, 0.80, 0.78), vec3(0.66, 0.66, 0.64), line * 0.6);
}

void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;  // both sides of a sheet are lit
  float diffuse = abs(dot(n, uLight)) * 0.25 + max(dot(n, uLight), 0.0) * 0.55;
  float light = 0.35 + diffuse;
  vec3 base = uMode == 0 ? woven(vRest) : (uMode == 1 ? vec3(0.62, 0.63, 0.65) : ground(vPosition));
  if (uMode == 2) light = 1.0;
  if (uMode == 0 && uTinted == 1) {
    // Column 0 at the smallest x, row 0 (texture t = 0) at the largest y (strength_map.h).
    vec2 st = vec2((vRest.x - uStrengthLo.x) / (uStrengthHi.x - uStrengthLo.x),
                   (uStrengthHi.y - vRest.y) / (uStrengthHi.y - uStrengthLo.y));
    vec4 tint = texture(uStrength, st);
    base = mix(base, tint.rgb, tint.a);
  }
  outColour = vec4(base * light, 1.0);
}
)";

// Lines and points in one flat colour.
const char* kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
void main() { gl_Position = uViewProjection * vec4(aPosition, 1.0); }
)";

const char* kFlatFragment = R"(#version 330 core
uniform vec3 uColour;
out vec4 outColour;
void main() { outColour = vec4(uColour, 1.0); }
)";

struct SurfaceVertex {
  float position[3];
  float normal[3];
  float rest[2];
};

void put3(float* out, const Vec3& v) {
  out[0] = static_cast<float>(v.x());
  out[1] = static_cast<float>(v.y());
  out[2] = static_cast<float>(v.z());
}

}  // namespace

struct SceneRenderer::Gl {
  GlProgram surface{"surface", kSurfaceVertex, kSurfaceFragment};
  GlProgram flat{"flat", kFlatVertex, kFlatFragment};
  GLuint vao = 0, surfaceBuffer = 0, lineBuffer = 0, strengthTexture = 0;
  // The map strengthTexture holds (kept, so that a new map at the same address is still new).
  std::shared_ptr<const TearStrengthMap> uploadedStrength;

  Gl() {
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &surfaceBuffer);
    glGenBuffers(1, &lineBuffer);
    glGenTextures(1, &strengthTexture);
  }
  ~Gl() {
    glDeleteTextures(1, &strengthTexture);
    glDeleteBuffers(1, &surfaceBuffer);
    glDeleteBuffers(1, &lineBuffer);
    glDeleteVertexArrays(1, &vao);
  }

  void drawSurface(const std::vector<SurfaceVertex>& vertices) {
    if (vertices.empty()) return;
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, surfaceBuffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(SurfaceVertex)), vertices.data(),
                 GL_STREAM_DRAW);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(SurfaceVertex),
                          reinterpret_cast<void*>(offsetof(SurfaceVertex, position)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(SurfaceVertex),
                          reinterpret_cast<void*>(offsetof(SurfaceVertex, normal)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(SurfaceVertex),
                          reinterpret_cast<void*>(offsetof(SurfaceVertex, rest)));
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  }

  void drawFlat(const std::vector<float>& positions, GLenum primitive) {
    if (positions.empty()) return;
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, lineBuffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(positions.size() * sizeof(float)), positions.data(),
                 GL_STREAM_DRAW);
    glDisableVertexAttribArray(1);
    glDisableVertexAttribArray(2);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    glDrawArrays(primitive, 0, static_cast<GLsizei>(positions.size() / 3));
  }
};

namespace {

// A tear strength multiplier as a colour over the cloth: below 1 towards red, above 1 towards
// blue, by how far it is from 1 on a log scale (0.25 or 4: fully), a neutral 1 not at all.
std::array<std::uint8_t, 4> strengthColour(double multiplier) {
  const double s = std::clamp(std::log(std::max(multiplier, 1e-6)) / std::log(4.0), -1.0, 1.0);
  const double a = 0.15 + 0.75 * std::abs(s);  // a faint wash where it is neutral: the map is on
  if (s < 0) return {230, 20, 20, static_cast<std::uint8_t>(std::lround(255 * a))};
  if (s > 0) return {25, 70, 230, static_cast<std::uint8_t>(std::lround(255 * a))};
  return {255, 255, 255, static_cast<std::uint8_t>(std::lround(255 * a))};
}

// The map's multipliers as an RGBA texture, row 0 first, bound to texture unit 0.
void uploadStrengthTexture(GLuint texture, const TearStrengthMap& map) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(map.width) * map.height * 4);
  for (std::size_t i = 0; i < map.multiplier.size() && 4 * i + 3 < rgba.size(); ++i) {
    const auto c = strengthColour(map.multiplier[i]);
    std::copy(c.begin(), c.end(), rgba.begin() + static_cast<std::ptrdiff_t>(4 * i));
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, map.width, map.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

SceneRenderer::SceneRenderer(const RenderSettings& settings) : settings_(settings), gl_(std::make_unique<Gl>()) {}

SceneRenderer::~SceneRenderer() = default;

namespace {

// Per-vertex normals from the current positions (area-weighted), de-indexed per triangle corner
// with the corner's material-space coordinates.
std::vector<SurfaceVertex> clothVertices(const ClothMesh& mesh) {
  std::vector<Vec3> normals(mesh.x.size(), Vec3::Zero());
  for (const Triangle& t : mesh.tris) {
    const Vec3 n = (mesh.x[t.v[1]] - mesh.x[t.v[0]]).cross(mesh.x[t.v[2]] - mesh.x[t.v[0]]);
    for (int k = 0; k < 3; ++k) normals[t.v[k]] += n;
  }
  std::vector<SurfaceVertex> out;
  out.reserve(mesh.tris.size() * 3);
  for (const Triangle& t : mesh.tris) {
    for (int k = 0; k < 3; ++k) {
      SurfaceVertex v{};
      put3(v.position, mesh.x[t.v[k]]);
      const double length = normals[t.v[k]].norm();
      put3(v.normal, length > 0 ? Vec3(normals[t.v[k]] / length) : Vec3(0, 1, 0));
      v.rest[0] = static_cast<float>(t.rest[k].x());
      v.rest[1] = static_cast<float>(t.rest[k].y());
      out.push_back(v);
    }
  }
  return out;
}

// Obstacles are faceted (tools have sharp edges): one normal per triangle.
std::vector<SurfaceVertex> obstacleVertices(const ObstacleView& o) {
  std::vector<SurfaceVertex> out;
  out.reserve(o.triangles.size() * 3);
  for (const auto& t : o.triangles) {
    Vec3 n = (o.vertices[t[1]] - o.vertices[t[0]]).cross(o.vertices[t[2]] - o.vertices[t[0]]);
    n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3(0, 1, 0);
    for (int k = 0; k < 3; ++k) {
      SurfaceVertex v{};
      put3(v.position, o.vertices[t[k]]);
      put3(v.normal, n);
      out.push_back(v);
    }
  }
  return out;
}

void appendSegment(std::vector<float>& out, const Vec3& a, const Vec3& b) {
  float p[6];
  put3(p, a);
  put3(p + 3, b);
  out.insert(out.end(), p, p + 6);
}

}  // namespace

void SceneRenderer::draw(const RenderView& view, const OrbitCamera& camera, int width, int height) {
  const auto& bg = settings_.background;
  glClearColor(bg[0], bg[1], bg[2], 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);

  const Eigen::Matrix4f viewProjection =
      camera.projection(static_cast<double>(width) / static_cast<double>(height)) * camera.view();
  Eigen::Vector3f light(settings_.lightDirection[0], settings_.lightDirection[1], settings_.lightDirection[2]);
  light.normalize();

  Gl& gl = *gl_;
  gl.surface.use();
  glUniformMatrix4fv(gl.surface.uniform("uViewProjection"), 1, GL_FALSE, viewProjection.data());
  glUniform3f(gl.surface.uniform("uLight"), light.x(), light.y(), light.z());

  // Surfaces are pushed back a little so that edges drawn on them win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 2.0f);

  if (view.groundHeight) {
    // A square around the camera's target reaching almost to the far plane (a near horizon).
    const double h = *view.groundHeight;
    const double r = 0.6 * camera.farPlane;
    const Vec3 c(camera.target.x(), h, camera.target.z());
    const Vec3 corners[4] = {c + Vec3(-r, 0, -r), c + Vec3(r, 0, -r), c + Vec3(r, 0, r), c + Vec3(-r, 0, r)};
    std::vector<SurfaceVertex> quad;
    for (int k : {0, 2, 1, 0, 3, 2}) {
      SurfaceVertex v{};
      put3(v.position, corners[k]);
      put3(v.normal, Vec3(0, 1, 0));
      quad.push_back(v);
    }
    glUniform1i(gl.surface.uniform("uMode"), 2);
    gl.drawSurface(quad);
  }

  glUniform1i(gl.surface.uniform("uMode"), 1);
  for (const ObstacleView& o : view.obstacles) gl.drawSurface(obstacleVertices(o));

  glUniform1i(gl.surface.uniform("uMode"), 0);
  for (const ClothView& cloth : view.cloths) {
    glUniform3f(gl.surface.uniform("uTint"), cloth.tint[0], cloth.tint[1], cloth.tint[2]);
    glUniform1f(gl.surface.uniform("uPitch"), static_cast<float>(cloth.threadPitch));
    glUniform1f(gl.surface.uniform("uBand"), static_cast<float>(cloth.threadsPerBand));
    glUniform1i(gl.surface.uniform("uPattern"), !cloth.woven ? 2 : cloth.pattern == WeavePattern::Plain ? 1 : 0);
    glUniform2f(gl.surface.uniform("uWeft"), static_cast<float>(std::cos(cloth.weftAngleRad)),
                static_cast<float>(std::sin(cloth.weftAngleRad)));
    const TearStrengthMap* tint = cloth.strengthTint.get();
    const bool tinted = tint != nullptr && tint->width > 0 && tint->height > 0 &&
                        tint->multiplier.size() == static_cast<std::size_t>(tint->width) * tint->height;
    glUniform1i(gl.surface.uniform("uTinted"), tinted ? 1 : 0);
    if (tinted) {
      if (gl.uploadedStrength != cloth.strengthTint) {  // a map changes per stroke, not per frame
        uploadStrengthTexture(gl.strengthTexture, *tint);
        gl.uploadedStrength = cloth.strengthTint;
      }
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, gl.strengthTexture);
      glUniform1i(gl.surface.uniform("uStrength"), 0);
      glUniform2f(gl.surface.uniform("uStrengthLo"), static_cast<float>(tint->lo.x()), static_cast<float>(tint->lo.y()));
      glUniform2f(gl.surface.uniform("uStrengthHi"), static_cast<float>(tint->hi.x()), static_cast<float>(tint->hi.y()));
    }
    gl.drawSurface(clothVertices(*cloth.mesh));
  }
  glUniform1i(gl.surface.uniform("uTinted"), 0);
  glDisable(GL_POLYGON_OFFSET_FILL);

  // Edges on top: torn red, cut green; sharp obstacle edges and vertices red.
  std::vector<float> torn, cut, sharpEdges, sharpPoints, highlightEdges, highlightPoints;
  for (const ClothView& cloth : view.cloths) {
    const ClothMesh& mesh = *cloth.mesh;
    for (const Edge& e : mesh.edges) {
      if (!settings_.markTornAndCutEdges) break;
      if (e.torn) appendSegment(torn, mesh.x[e.v[0]], mesh.x[e.v[1]]);
      if (e.cut) appendSegment(cut, mesh.x[e.v[0]], mesh.x[e.v[1]]);
    }
  }
  for (const ObstacleView& o : view.obstacles) {
    for (const auto& e : o.sharpEdges) appendSegment(sharpEdges, o.vertices[e[0]], o.vertices[e[1]]);
    for (int v : o.sharpVertices) {
      float p[3];
      put3(p, o.vertices[v]);
      sharpPoints.insert(sharpPoints.end(), p, p + 3);
    }
    for (const auto& e : o.highlightEdges) appendSegment(highlightEdges, o.vertices[e[0]], o.vertices[e[1]]);
    for (int v : o.highlightVertices) {
      float p[3];
      put3(p, o.vertices[v]);
      highlightPoints.insert(highlightPoints.end(), p, p + 3);
    }
  }
  gl.flat.use();
  glUniformMatrix4fv(gl.flat.uniform("uViewProjection"), 1, GL_FALSE, viewProjection.data());
  glLineWidth(settings_.lineWidth);
  glPointSize(2.0f * settings_.lineWidth + 1.0f);
  const GLint colour = gl.flat.uniform("uColour");
  glUniform3f(colour, 0.85f, 0.05f, 0.05f);
  gl.drawFlat(torn, GL_LINES);
  gl.drawFlat(sharpEdges, GL_LINES);
  gl.drawFlat(sharpPoints, GL_POINTS);
  glUniform3f(colour, 0.05f, 0.70f, 0.10f);
  gl.drawFlat(cut, GL_LINES);
  // The editor's hover highlight: wider and amber, so it reads on a red (already sharp) edge too.
  if (!highlightEdges.empty() || !highlightPoints.empty()) {
    glLineWidth(2.0f * settings_.lineWidth);
    glPointSize(4.0f * settings_.lineWidth + 2.0f);
    glUniform3f(colour, 1.0f, 0.65f, 0.0f);
    gl.drawFlat(highlightEdges, GL_LINES);
    gl.drawFlat(highlightPoints, GL_POINTS);
  }
  glBindVertexArray(0);
  // Wide lines are optional in a core context; a driver that refuses them draws 1 px lines.
  while (glGetError() != GL_NO_ERROR) {
  }
}

}  // namespace weft::ui
