// docs/model-format.md shows, for every table of a model file, the key table that
// key_table_markdown() generates from the field tables: a key is declared once, and
// the documentation cannot drift from what the reader accepts.

#include <feran/io/key_reference.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/spec/fields.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

namespace feran::test_key_reference {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(KeyReference, TheModelFormatDocumentShowsTheGeneratedTables) {
  const std::string doc = read(std::string(FERAN_SOURCE_DIR) + "/docs/model-format.md");
  ASSERT_FALSE(doc.empty());
  for (const std::string& table : documented_tables()) {
    SCOPED_TRACE(table);
    const std::string begin = "<!-- keys: " + table + " ";
    const std::size_t at = doc.find(begin);
    ASSERT_NE(at, std::string::npos) << "docs/model-format.md has no block for " << table;
    const std::size_t start = doc.find('\n', at) + 1;
    const std::size_t end = doc.find("<!-- end keys -->", start);
    ASSERT_NE(end, std::string::npos);
    EXPECT_EQ(doc.substr(start, end - start), key_table_markdown(table))
        << "replace the block of " << table << " in docs/model-format.md with the text above";
  }
}

TEST(KeyReference, EveryDocumentedKeyIsAcceptedAndEveryTableListed) {
  // The tables are those the reader accepts: each is listed once, sections under shafts.
  const auto tables = documented_tables();
  std::size_t visited = 0;
  const ModelSpec empty;
  spec::visit_tables(empty, [&](std::string_view key, spec::TableForm, std::string_view, const auto&) {
    ++visited;
    EXPECT_EQ(std::count(tables.begin(), tables.end(), key), 1) << key;
  });
  EXPECT_EQ(tables.size(), visited + 1);  // and the shafts' sections
  EXPECT_EQ(tables.front(), "options");
  EXPECT_EQ(tables[3], "shafts.sections");
  EXPECT_THROW((void)key_table_markdown("shaft"), Error);
  // A key from the generated table of [[unbalances]] reads; one that is not in it does not.
  const std::string base =
      "[[materials]]\nname = \"s\"\nE = 2e11\nnu = 0.3\nrho = 7800\n"
      "[[shafts]]\nmaterial = \"s\"\nsections = [{ length = 0.1, outer_diameter = 0.01 }]\n"
      "[[fixed]]\nnode = 1\n[[unbalances]]\nnode = 2\nmass = 0.001\nradius = 0.01\n";
  EXPECT_NE(key_table_markdown("unbalances").find("| `lever` |"), std::string::npos);
  EXPECT_NO_THROW((void)read_model_string(base + "lever = 0.01\n", "inline"));
  EXPECT_EQ(key_table_markdown("unbalances").find("| `levr` |"), std::string::npos);
  EXPECT_THROW((void)read_model_string(base + "levr = 0.01\n", "inline"), ModelError);
}

}  // namespace
}  // namespace feran::test_key_reference
