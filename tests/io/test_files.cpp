#include <tessera/io/files.hpp>

#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

namespace {
std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("tessera_test_files_") + name)).string();
}
}  // namespace

TEST_CASE("files: write_file then read_file round-trips every byte, empty included", "[files]") {
  const std::string path = temp_path("roundtrip.bin");
  std::string data = "line 1\r\nline 2\n";
  data.push_back('\0');
  data.push_back(static_cast<char>(0xff));
  data += std::string(200000, 'x');  // longer than the reader's 64 KiB chunk
  REQUIRE(tessera::write_file(path, data));
  auto back = tessera::read_file(path);
  REQUIRE(back);
  CHECK(*back == data);
  REQUIRE(tessera::write_file(path, std::string_view{}));
  back = tessera::read_file(path);
  REQUIRE(back);
  CHECK(back->empty());
  std::filesystem::remove(path);
}

TEST_CASE("files: errors are io_errors naming the file", "[files]") {
  const std::string missing = temp_path("does_not_exist/none.txt");
  const auto r = tessera::read_file(missing);
  REQUIRE_FALSE(r);
  CHECK(r.error().code() == tessera::status_code::io_error);
  CHECK_THAT(r.error().message(), Catch::Contains(missing) && Catch::Contains("cannot open"));
  const auto w = tessera::write_file(missing, "x");
  REQUIRE_FALSE(w);
  CHECK(w.code() == tessera::status_code::io_error);
  CHECK_THAT(w.message(), Catch::Contains(missing));
  // a directory opens on Linux but cannot be read as a file
  const std::string dir = std::filesystem::temp_directory_path().string();
  const auto d = tessera::read_file(dir);
  REQUIRE_FALSE(d);
  CHECK_THAT(d.error().message(), Catch::Contains(dir));
}

TEST_CASE("files: file_extension is the lower-case suffix of the last path component", "[files]") {
  CHECK(tessera::file_extension("Mesh.OBJ") == "obj");
  CHECK(tessera::file_extension("dir/a.b/c.PnG") == "png");
  CHECK(tessera::file_extension("dir.v2/noext") == "");
  CHECK(tessera::file_extension("dir.v2\\noext") == "");
  CHECK(tessera::file_extension("noext") == "");
  CHECK(tessera::file_extension("trailing.") == "");
  CHECK(tessera::file_extension("") == "");
  CHECK(tessera::file_extension(".hidden") == "hidden");
}

TEST_CASE("files: cat words messages from strings, numbers, booleans and enums", "[files]") {
  enum class e { a, b };
  CHECK(tessera::cat("w = ", 3, ", x = ", 0.5, ", ok = ", true, ", c = ", 'q', ", e = ", e::b) ==
        "w = 3, x = 0.5, ok = true, c = q, e = 1");
  CHECK(tessera::cat() == "");
  CHECK(tessera::cat(static_cast<const char*>(nullptr)) == "(null)");
}
