// Provenance records (api/provenance.h): SHA-256 against FIPS 180-2's
// examples, the record's JSON, and the record embedded by each real writer,
// found again by readers written here (a PNG chunk walker, OBJ and PLY
// header lines, the GLB's JSON chunk) and by read_run_record.
#include "api/provenance.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "api/outputs.h"
#include "api/simulation.h"
#include "test_support.h"

namespace sylva::test {
namespace {

namespace fs = std::filesystem;

TEST(Sha256, FipsExamples) {
  // FIPS 180-2, appendix B.1 and B.2; and the empty message.
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  // Fed in pieces, the same digest.
  Sha256 pieces;
  pieces.add("ab");
  pieces.add("");
  pieces.add("c");
  EXPECT_EQ(pieces.hex(), sha256_hex("abc"));
}

TEST(Sha256, OfAFile) {
  const std::string path = write_temp_file("provenance-sha", "abc.txt", "abc");
  EXPECT_EQ(file_sha256(path), sha256_hex("abc"));
  EXPECT_EQ(file_sha256(path + ".missing"), std::nullopt);
}

RunRecord full_record() {
  RunRecord r;
  r.sylva_version = "0.1.0";
  r.model = {"/models/plant é.l", sha256_hex("model"), "", 1};
  r.inputs = {{"/models/plant.v", sha256_hex("view"), "view", 1}, {"/models/b.map", sha256_hex("map"), "colormap", 2}};
  r.defines = {"N=3", "FAST", "S=\"a b\""};
  r.seed = 9007199254740993L;  // past a double's exact integers
  r.language = "lc";
  r.keyed_random = true;
  r.cpfg_window_seeding = true;
  r.axiom_from = HashedFile{"/models/start.str", sha256_hex("start"), "", 1};
  r.compiler = "g++";
  r.compiler_version = "g++ (Debian 12.2.0-14) 12.2.0";
  r.step = 7;
  r.time = 2.5;
  r.finished = true;
  r.continuous = ContinuousRecord{"rk4", 0.1, 0.5, 1e-7, 1e-10, 1e-8, 10, 5};
  r.string_sha256 = sha256_hex("A B\n");
  return r;
}

TEST(RunRecord, JsonRoundTrips) {
  const RunRecord full = full_record();
  const std::string text = run_record_json(full);
  EXPECT_EQ(text.find('\n'), std::string::npos) << "one line";
  for (unsigned char c : text) EXPECT_LT(c, 0x80) << "ASCII: " << text;
  EXPECT_EQ(parse_run_record(text, "test"), full);
  const nlohmann::json j = full;
  EXPECT_EQ(j.get<RunRecord>(), full);
  EXPECT_EQ(j["seed"].get<long>(), 9007199254740993L);

  // A plain run: no seed, no time, no continuous settings.
  RunRecord plain;
  plain.model = {"/m.l", sha256_hex("m"), "", 1};
  plain.string_sha256 = sha256_hex("");
  const nlohmann::json p = plain;
  EXPECT_FALSE(p.contains("seed"));
  EXPECT_FALSE(p.contains("time"));
  EXPECT_EQ(parse_run_record(run_record_json(plain), "test"), plain);
}

TEST(RunRecord, MalformedJsonIsAnErrorNamingTheSource) {
  try {
    parse_run_record("{\"model\": 3}", "x.json");
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("x.json"), std::string::npos) << e.what();
  }
}

// ---- records in the files the real writers write

// A PNG's chunks, walked here rather than by the code under test: the
// signature, then length, type, data, CRC (checked) until IEND.
std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

struct PngChunk {
  std::string type, data;
};

std::vector<PngChunk> png_chunks(const std::string& png) {
  std::vector<PngChunk> chunks;
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  auto u32 = [&](std::size_t at) {
    return std::uint32_t{static_cast<unsigned char>(png[at])} << 24 |
           std::uint32_t{static_cast<unsigned char>(png[at + 1])} << 16 |
           std::uint32_t{static_cast<unsigned char>(png[at + 2])} << 8 | static_cast<unsigned char>(png[at + 3]);
  };
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length = u32(at);
    PngChunk chunk{png.substr(at + 4, 4), png.substr(at + 8, length)};
    EXPECT_EQ(u32(at + 8 + length), crc32(chunk.type + chunk.data)) << "CRC of " << chunk.type;
    chunks.push_back(chunk);
    at += 12 + length;
    if (chunk.type == "IEND") {
      EXPECT_EQ(at, png.size());
      break;
    }
  }
  return chunks;
}

// The rest of the first line of `text` that starts with `prefix`.
std::string line_after(const std::string& text, const std::string& prefix) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
  return {};
}

class WrittenRecords : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("provenance-writers");
    std::ofstream(dir_ + "/model.l") << "#include <lpfgall.h>\nderivation length: 2;\nmodule A(int);\n"
                                        "Axiom: A(0);\nA(n) : { produce F(1) Left(30) A(n + 1); }\n";
    std::ofstream(dir_ + "/view.v") << "line style: cylinder\n";
    options_.build.cache_dir = SYLVA_TEST_CACHE_DIR;
    options_.build.defines = {"UNUSED=1"};
    options_.input_files.push_back(dir_ + "/view.v");
  }
  std::string dir_;
  SimulationOptions options_;
};

TEST_F(WrittenRecords, EveryFormatCarriesTheRecordOfTheStateItShows) {
  Simulation simulation(dir_ + "/model.l", options_);
  const RunRecord base = make_run_record(simulation, options_);
  EXPECT_EQ(base.model.path, fs::path(dir_ + "/model.l").lexically_normal().string());
  EXPECT_EQ(base.model.sha256, file_sha256(dir_ + "/model.l"));
  ASSERT_EQ(base.inputs.size(), 1u);
  EXPECT_EQ(base.inputs[0].kind, "view");
  EXPECT_EQ(base.inputs[0].sha256, sha256_hex("line style: cylinder\n"));
  EXPECT_EQ(base.defines, std::vector<std::string>{"UNUSED=1"});
  EXPECT_FALSE(base.compiler.empty());
  EXPECT_FALSE(base.compiler_version.empty());
  EXPECT_FALSE(base.sylva_version.empty());

  const std::vector<std::string> names = {"out.png", "out.obj", "out.ply", "out.glb",
                                          "out.svg", "out.ps",  "out.eps", "out.pdf"};
  std::vector<std::string> paths;
  for (const std::string& name : names) paths.push_back(dir_ + "/" + name);
  RunRecord expected;
  {
    ProvenanceScope scope(simulation, base);
    simulation.run();
    simulation.write(paths);
    expected = complete_run_record(base, simulation);
  }
  EXPECT_EQ(expected.step, 2);
  EXPECT_TRUE(expected.finished);
  EXPECT_EQ(expected.string_sha256, sha256_hex(simulation.string_text()));
  const std::string json = run_record_json(expected);

  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    const std::optional<RunRecord> read = read_run_record(path);
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(*read, expected);
  }

  // PNG: one tEXt chunk after IHDR, found by the walker above.
  const std::vector<PngChunk> chunks = png_chunks(read_text(dir_ + "/out.png"));
  ASSERT_GE(chunks.size(), 3u);
  EXPECT_EQ(chunks[0].type, "IHDR");
  EXPECT_EQ(chunks[1].type, "tEXt");
  EXPECT_EQ(chunks[1].data, std::string("sylva:provenance") + '\0' + json);
  EXPECT_EQ(chunks.back().type, "IEND");

  // OBJ: a comment near the top; assimp still reads the mesh.
  const std::string obj = read_text(dir_ + "/out.obj");
  EXPECT_EQ(line_after(obj, "# sylva:provenance "), json);
  EXPECT_LT(obj.find("# sylva:provenance "), obj.find("\nv "));
  // PLY: a header comment.
  const std::string ply = read_text(dir_ + "/out.ply");
  EXPECT_EQ(line_after(ply.substr(0, ply.find("end_header")), "comment sylva:provenance "), json);
  for (const char* mesh : {"out.obj", "out.ply", "out.glb"}) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(dir_ + "/" + mesh, 0);
    ASSERT_NE(scene, nullptr) << mesh << ": " << importer.GetErrorString();
    EXPECT_GT(scene->mNumMeshes, 0u) << mesh;
  }
  // GLB: asset.extras in the JSON chunk.
  const std::string glb = read_text(dir_ + "/out.glb");
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  const nlohmann::json gltf = nlohmann::json::parse(glb.substr(20, json_length));
  EXPECT_EQ(gltf["asset"]["extras"]["sylva:provenance"].get<std::string>(), json);
  EXPECT_EQ(gltf["asset"]["version"], "2.0");
  // SVG: a metadata element; PostScript: a header comment.
  EXPECT_NE(read_text(dir_ + "/out.svg").find("<metadata id=\"sylva-provenance\">"), std::string::npos);
  for (const char* ps : {"out.ps", "out.eps"}) {
    const std::string text = read_text(dir_ + "/" + ps);
    EXPECT_EQ(line_after(text, "%%sylva:provenance "), json) << ps;
    EXPECT_LT(text.find("%%sylva:provenance"), text.find("%%EndComments")) << ps;
  }
}

TEST_F(WrittenRecords, FramesRecordTheirStepAndStringFramesHaveASidecar) {
  Simulation simulation(dir_ + "/model.l", options_);
  ProvenanceScope scope(simulation, make_run_record(simulation, options_));
  const std::string frames = dir_ + "/frames";
  ASSERT_EQ(write_frames(frames, simulation, {64, 64}, -1, {"obj", "str"}), 3);
  for (int step = 0; step <= 2; ++step) {
    SCOPED_TRACE(step);
    const std::string stem = frames + "/frame-000" + std::to_string(step);
    const std::optional<RunRecord> obj = read_run_record(stem + ".obj");
    const std::optional<RunRecord> str = read_run_record(stem + ".str");
    ASSERT_TRUE(obj && str);
    EXPECT_EQ(obj->step, step);
    EXPECT_EQ(*obj, *str);
    EXPECT_EQ(obj->string_sha256, sha256_hex(read_text(stem + ".str")));
    // The string itself is untouched: what lpfg's readers take.
    EXPECT_EQ(read_text(stem + ".str").find("sylva"), std::string::npos);
    EXPECT_TRUE(fs::exists(stem + ".str.provenance.json"));
  }
}

TEST_F(WrittenRecords, WithoutAScopeNoRecord) {
  Simulation simulation(dir_ + "/model.l", options_);
  simulation.run();
  simulation.write({dir_ + "/plain.obj", dir_ + "/plain.png"});
  EXPECT_EQ(read_run_record(dir_ + "/plain.obj"), std::nullopt);
  EXPECT_EQ(read_run_record(dir_ + "/plain.png"), std::nullopt);
  EXPECT_EQ(read_text(dir_ + "/plain.obj").find("sylva:provenance"), std::string::npos);
}

}  // namespace
}  // namespace sylva::test
