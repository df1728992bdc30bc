// Writes synthetic assets for the scaling benchmarks (bench/run.sh):
//   bench_generate urdf-chain  N out.urdf   N revolute joints in one chain
//   bench_generate urdf-tree   N out.urdf   N revolute joints, all children of the base
//   bench_generate urdf-mimic  N out.urdf   a chain; every second joint mimics the one before
//   bench_generate usda-stage  MB JOINTS out.usda
//        a stage of about MB megabytes: JOINTS revolute joints with drives and limits,
//        one rigid body per joint, each with a triangle mesh carrying the bulk of the bytes
// The files are valid, physically plausible and deterministic (no randomness).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: bench_generate urdf-chain|urdf-tree|urdf-mimic JOINTS out.urdf\n"
               "       bench_generate usda-stage MEGABYTES JOINTS out.usda\n");
  return 2;
}

void urdf_link(std::FILE* out, long i) {
  std::fprintf(out,
               "  <link name=\"link%ld\">\n"
               "    <inertial><origin xyz=\"0 0 0.05\" rpy=\"0 0 0\"/><mass value=\"0.5\"/>"
               "<inertia ixx=\"0.001\" ixy=\"0\" ixz=\"0\" iyy=\"0.001\" iyz=\"0\" izz=\"0.0005\"/></inertial>\n"
               "    <visual><geometry><cylinder radius=\"0.02\" length=\"0.1\"/></geometry></visual>\n"
               "  </link>\n",
               i);
}

// kind: 0 chain, 1 wide tree, 2 mimic chain.
void write_urdf(std::FILE* out, int kind, long joints) {
  std::fprintf(out, "<?xml version=\"1.0\"?>\n<robot name=\"synthetic\">\n");
  urdf_link(out, 0);
  for (long i = 1; i <= joints; ++i) {
    urdf_link(out, i);
    const long parent = kind == 1 ? 0 : i - 1;
    std::fprintf(out,
                 "  <joint name=\"joint%ld\" type=\"revolute\">\n"
                 "    <parent link=\"link%ld\"/><child link=\"link%ld\"/>\n"
                 "    <origin xyz=\"0 0 0.1\" rpy=\"0 0 0\"/><axis xyz=\"0 0 1\"/>\n"
                 "    <limit lower=\"-1.5\" upper=\"1.5\" effort=\"20\" velocity=\"3\"/>\n",
                 i, parent, i);
    if (kind == 2 && i % 2 == 0) std::fprintf(out, "    <mimic joint=\"joint%ld\" multiplier=\"1\" offset=\"0\"/>\n", i - 1);
    std::fprintf(out, "  </joint>\n");
  }
  std::fprintf(out, "</robot>\n");
}

// A grid mesh of about `vertices` points (rows of 32) written as USD arrays; returns
// the number of points written.
long usda_mesh(std::FILE* out, long body, long vertices) {
  const long columns = 32;
  const long rows = vertices / columns < 2 ? 2 : vertices / columns;
  std::fprintf(out, "            def Mesh \"shape\"\n            {\n                int[] faceVertexCounts = [");
  const long quads = (rows - 1) * (columns - 1);
  for (long q = 0; q < quads; ++q) std::fputs(q ? ", 4" : "4", out);
  std::fputs("]\n                int[] faceVertexIndices = [", out);
  for (long r = 0; r + 1 < rows; ++r)
    for (long c = 0; c + 1 < columns; ++c) {
      const long v = r * columns + c;
      std::fprintf(out, "%s%ld, %ld, %ld, %ld", (r || c) ? ", " : "", v, v + 1, v + columns + 1, v + columns);
    }
  std::fputs("]\n                point3f[] points = [", out);
  for (long r = 0; r < rows; ++r)
    for (long c = 0; c < columns; ++c)
      std::fprintf(out, "%s(%.4f, %.4f, %.4f)", (r || c) ? ", " : "", 0.001 * static_cast<double>(c),
                   0.001 * static_cast<double>(r), 0.0001 * static_cast<double>(body % 97));
  std::fputs("]\n                uniform token subdivisionScheme = \"none\"\n            }\n", out);
  return rows * columns;
}

// Bytes of one joint prim as write_usda writes it (about; only used to size the meshes).
constexpr double kJointBytes = 640;

void write_usda(std::FILE* out, double megabytes, long joints) {
  std::fprintf(out,
               "#usda 1.0\n(\n    defaultPrim = \"robot\"\n    metersPerUnit = 1\n    kilogramsPerUnit = 1\n)\n\n"
               "def PhysicsScene \"physicsScene\" (\n    prepend apiSchemas = [\"PhysxSceneAPI\"]\n)\n"
               "{\n    uniform float physxScene:timeStepsPerSecond = 60\n}\n\n"
               "def Xform \"robot\" (\n    prepend apiSchemas = [\"PhysxArticulationAPI\"]\n)\n{\n"
               "    int physxArticulation:solverPositionIterationCount = 32\n");
  // The meshes carry the bulk of the bytes. Each body's mesh is sized from the bytes still
  // missing and the bytes per vertex the previous mesh took, so the file lands near the target.
  const double target = megabytes * 1e6 - kJointBytes * static_cast<double>(joints);
  double bytes_per_vertex = 50;
  for (long i = 0; i <= joints; ++i) {
    std::fprintf(out,
                 "    def Xform \"link%ld\" (\n        prepend apiSchemas = [\"PhysicsRigidBodyAPI\", \"PhysicsMassAPI\"]\n    )\n    {\n"
                 "        float physics:mass = 0.5\n        float3 physics:diagonalInertia = (0.001, 0.001, 0.0005)\n"
                 "        point3f physics:centerOfMass = (0, 0, 0.05)\n"
                 "        def Xform \"geometry\"\n        {\n",
                 i);
    const double missing = target - static_cast<double>(std::ftell(out));
    const long vertices = static_cast<long>(missing / bytes_per_vertex / static_cast<double>(joints + 1 - i));
    const long before = std::ftell(out);
    const long written = usda_mesh(out, i, vertices);
    bytes_per_vertex = static_cast<double>(std::ftell(out) - before) / static_cast<double>(written);
    std::fputs("        }\n    }\n", out);
  }
  std::fputs("    def Scope \"joints\"\n    {\n", out);
  for (long i = 1; i <= joints; ++i) {
    std::fprintf(out,
                 "        def PhysicsRevoluteJoint \"joint%ld\" (\n"
                 "            prepend apiSchemas = [\"PhysicsDriveAPI:angular\", \"PhysxJointAPI\"]\n        )\n"
                 "        {\n            rel physics:body0 = </robot/link%ld>\n            rel physics:body1 = </robot/link%ld>\n"
                 "            uniform token physics:axis = \"Z\"\n            float physics:lowerLimit = -90\n"
                 "            float physics:upperLimit = 90\n            float drive:angular:physics:stiffness = 0.5\n"
                 "            float drive:angular:physics:damping = 0.001\n            float drive:angular:physics:maxForce = 20\n"
                 "            float physxJoint:maxJointVelocity = 170\n        }\n",
                 i, i - 1, i);
  }
  std::fputs("    }\n}\n", out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) return usage();
  const std::string_view kind = argv[1];
  const char* path = argv[argc - 1];
  std::FILE* out = std::fopen(path, "wb");
  if (!out) {
    std::perror(path);
    return 2;
  }
  static char buffer[1 << 20];
  std::setvbuf(out, buffer, _IOFBF, sizeof buffer);
  if (kind == "usda-stage" && argc == 5) {
    write_usda(out, std::atof(argv[2]), std::atol(argv[3]));
  } else if (argc == 4 && (kind == "urdf-chain" || kind == "urdf-tree" || kind == "urdf-mimic")) {
    write_urdf(out, kind == "urdf-chain" ? 0 : kind == "urdf-tree" ? 1 : 2, std::atol(argv[2]));
  } else {
    std::fclose(out);
    return usage();
  }
  return std::fclose(out) == 0 ? 0 : 2;
}
