// docs/messages.md's message table lists exactly the catalog (scripts rely on the documented numbers).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "common/messages.h"

TEST(MessageCatalog, ReadmeTableMatchesTheCatalog) {
  std::ifstream in(std::string(IMPACT3D_SOURCE_DIR) + "/docs/messages.md");
  ASSERT_TRUE(in) << "docs/messages.md not found";
  std::set<std::pair<int, std::string>> documented;
  const std::regex row(R"(^\| (\d{4}) \| (error|warning|info) \| (.*) \|$)");
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, row)) documented.insert({std::stoi(m[1]), m[3]});
  }
  std::set<std::pair<int, std::string>> catalog;
  for (const auto& d : impact3d::message_catalog()) {
    std::string text = d.text;
    // the table escapes '|' in table cells
    for (std::size_t p = 0; (p = text.find('|', p)) != std::string::npos; p += 2) text.insert(p, "\\");
    catalog.insert({d.id, text});
  }
  EXPECT_EQ(documented, catalog) << "regenerate the table of docs/messages.md from `impact3d --messages`";
}
