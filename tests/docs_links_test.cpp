// The documentation lives in the repository: every relative link in README.md
// and docs/*.md names a file inside the repository, and every #anchor names a
// heading of the file it points into. A link to a file outside the checkout
// (once `../shared/SPEC.md`) is broken in every clone, so it fails here before
// a reader finds it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The repository root as the build knows it, canonical so that prefix tests
// compare like with like (no symbolic links, no `..`).
fs::path root() { return fs::canonical(PRISM_SOURCE_DIR); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// The documents checked: the README and every markdown file in docs/.
std::vector<fs::path> documents() {
  std::vector<fs::path> files{root() / "README.md"};
  for (const fs::directory_entry& e : fs::directory_iterator(root() / "docs"))
    if (e.is_regular_file() && e.path().extension() == ".md") files.push_back(e.path());
  std::sort(files.begin() + 1, files.end());
  return files;
}

bool isFence(const std::string& line) {
  const std::size_t i = line.find_first_not_of(' ');
  return i != std::string::npos && i <= 3 &&
         (line.compare(i, 3, "```") == 0 || line.compare(i, 3, "~~~") == 0);
}

// The lines as a reader of the rendered page sees links and headings in them:
// fenced code blocks blanked (a `# comment` in a shell block is no heading,
// `a[i](x)` in C++ no link) and inline code spans replaced by their text
// without the backticks' power (GitHub renders no link inside them either).
std::vector<std::string> proseLines(const std::string& text) {
  std::vector<std::string> lines = linesOf(text);
  bool inFence = false;
  for (std::string& line : lines) {
    if (isFence(line)) {
      inFence = !inFence;
      line.clear();
      continue;
    }
    if (inFence) {
      line.clear();
      continue;
    }
    // A code span's brackets and parentheses would otherwise look like link
    // syntax; they become spaces, the rest of the span stays (headings keep
    // their words for the slug).
    std::string out;
    bool inCode = false;
    for (char c : line) {
      if (c == '`') {
        inCode = !inCode;
        continue;
      }
      out += inCode && (c == '[' || c == ']' || c == '(' || c == ')') ? ' ' : c;
    }
    line = out;
  }
  return lines;
}

// GitHub's anchor for a heading: lower case; every character but letters,
// digits, spaces, hyphens and underscores dropped; spaces become hyphens.
// Non-ASCII letters are kept (only Latin-1's are lower-cased, enough for
// these documents); general punctuation such as an en dash is dropped.
std::string slugOf(const std::string& heading) {
  // Link syntax in a heading renders as its text.
  const std::string text =
      std::regex_replace(heading, std::regex(R"(!?\[([^\]]*)\]\([^)]*\))"), "$1");
  std::string slug;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if (std::isalnum(c) != 0 || c == '-' || c == '_')
        slug += char(std::tolower(c));
      else if (c == ' ')
        slug += '-';
      ++i;
      continue;
    }
    // Decode one UTF-8 code point.
    const std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
    unsigned cp = c & (n == 2 ? 0x1Fu : n == 3 ? 0x0Fu : 0x07u);
    for (std::size_t k = 1; k < n && i + k < text.size(); ++k)
      cp = (cp << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3Fu);
    const bool punctuation = (cp >= 0x80 && cp <= 0xBF) || cp == 0xD7 || cp == 0xF7 ||
                             (cp >= 0x2000 && cp <= 0x2BFF) || (cp >= 0x3000 && cp <= 0x303F);
    if (!punctuation) {
      if (cp >= 0xC0 && cp <= 0xDE) cp += 0x20; // Latin-1 upper case to lower case
      if (cp < 0x800) {
        slug += char(0xC0 | (cp >> 6));
        slug += char(0x80 | (cp & 0x3F));
      } else {
        slug.append(text, i, n);
      }
    }
    i += n;
  }
  return slug;
}

// Every anchor a markdown file offers: ATX headings (`## Title`) and setext
// headings (a line of `=` or `-` under a line of text); a repeated slug gets
// -1, -2, ... as on GitHub.
std::set<std::string> anchorsOf(const fs::path& file) {
  const std::vector<std::string> lines = proseLines(slurp(file));
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  auto add = [&](std::string title) {
    title = std::regex_replace(title, std::regex(R"(^\s+|\s+#*\s*$|\s+$)"), "");
    const std::string slug = slugOf(title);
    const int n = seen[slug]++;
    anchors.insert(n == 0 ? slug : slug + "-" + std::to_string(n));
  };
  const std::regex atx(R"(^ {0,3}#{1,6}\s+(.*)$)");
  const std::regex setext(R"(^ {0,3}(=+|-+)\s*$)");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (std::regex_match(lines[i], m, atx)) {
      add(m[1]);
    } else if (i > 0 && std::regex_match(lines[i], setext) && !lines[i - 1].empty() &&
               lines[i - 1].find('|') == std::string::npos &&
               !std::regex_match(lines[i - 1], atx)) {
      add(lines[i - 1]);
    }
  }
  return anchors;
}

struct Link {
  fs::path file; // the document holding it
  int line = 0;
  std::string target;
};

// Inline links and images `[text](target "title")`, reference definitions
// `[name]: target`, and HTML `src="..."` / `href="..."`.
std::vector<Link> linksOf(const fs::path& file) {
  std::vector<Link> links;
  const std::vector<std::string> lines = proseLines(slurp(file));
  const std::regex inlineLink(R"(\]\(\s*<?([^)\s>]*)>?(?:\s+"[^"]*")?\s*\))");
  const std::regex definition(R"(^ {0,3}\[[^\]]+\]:\s*<?([^\s>]+)>?)");
  const std::regex html(R"re((?:src|href)\s*=\s*"([^"]*)")re");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (const std::regex* r : {&inlineLink, &definition, &html})
      for (std::sregex_iterator it(lines[i].begin(), lines[i].end(), *r), end; it != end; ++it)
        links.push_back({file, int(i) + 1, (*it)[1]});
  }
  return links;
}

bool isExternal(const std::string& target) {
  return target.starts_with("http://") || target.starts_with("https://") ||
         target.starts_with("mailto:");
}

std::string percentDecoded(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

// Whether `p` (canonical) is `base` or lies below it, compared component by
// component: /work/main2 is not inside /work/main.
bool isInside(const fs::path& p, const fs::path& base) {
  return std::mismatch(base.begin(), base.end(), p.begin(), p.end()).first == base.end();
}

std::string where(const Link& l) {
  return fs::relative(l.file, root()).string() + ":" + std::to_string(l.line) + ": (" + l.target +
         ")";
}

// What is wrong with a link, or "" when it resolves inside the repository
// rooted at `base` (canonical) and its anchor names a heading there.
std::string problemWith(const Link& link, const fs::path& base = root()) {
  const std::string& target = link.target;
  if (target.empty()) return "empty link target";
  if (isExternal(target)) return "";
  // Any other scheme (file:, ftp:, ...) names something outside the checkout.
  if (std::regex_search(target, std::regex("^[A-Za-z][A-Za-z0-9+.-]*:")))
    return "a URL that is not http(s) or mailto";
  const std::size_t hash = target.find('#');
  const std::string path = percentDecoded(target.substr(0, hash));
  const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);

  fs::path resolved = link.file;
  if (!path.empty()) {
    std::error_code ec;
    resolved = fs::weakly_canonical(link.file.parent_path() / path, ec);
    if (ec) return "cannot resolve: " + ec.message();
    if (!isInside(resolved, base)) return "points outside the repository: " + resolved.string();
    if (!fs::exists(resolved)) return "no such file: " + resolved.string();
  }
  if (hash != std::string::npos) {
    if (resolved.extension() != ".md") return "an anchor into a file that is not markdown";
    if (!anchorsOf(resolved).count(anchor))
      return "no heading with the anchor #" + anchor + " in " +
             fs::relative(resolved, base).string();
  }
  return "";
}

TEST(DocsLinks, TheCheckerFindsLinksAnchorsAndHeadings) {
  // The checker's own parts, on text whose answer is known, so that a test
  // that passes means the documents are right rather than the parser blind.
  EXPECT_EQ(slugOf("Running `prism render`"), "running-prism-render");
  EXPECT_EQ(slugOf("Importing NFF and OBJ"), "importing-nff-and-obj");
  EXPECT_EQ(slugOf("1.2 Depth: what D = 1 means"), "12-depth-what-d--1-means");
  EXPECT_EQ(slugOf("`--accel bvh|groups|none`"), "--accel-bvhgroupsnone");
  EXPECT_EQ(slugOf("Sections 1–4"), "sections-14");
  EXPECT_EQ(slugOf("See [the model](docs/x.md)"), "see-the-model");
  EXPECT_EQ(slugOf("Écrit à la main"), "écrit-à-la-main");

  const std::vector<std::string> prose = proseLines(
      "a [link](x.md) and `a[i](j)`\n```\n# not a heading\n[no](link.md)\n```\n# Title\n");
  ASSERT_EQ(prose.size(), 6u);
  EXPECT_EQ(prose[0], "a [link](x.md) and a i  j ");
  EXPECT_EQ(prose[2], "");
  EXPECT_EQ(prose[3], "");
  EXPECT_EQ(prose[5], "# Title");

  EXPECT_TRUE(isInside(fs::path("/a/b/c"), fs::path("/a/b")));
  EXPECT_TRUE(isInside(fs::path("/a/b"), fs::path("/a/b")));
  EXPECT_FALSE(isInside(fs::path("/a/bc"), fs::path("/a/b")));
  EXPECT_FALSE(isInside(fs::path("/a"), fs::path("/a/b")));

  // Links resolved in a small repository of the test's own, beside a
  // folder that stands for `../shared`, so the verdicts do not depend on
  // what the real documents say.
  const fs::path scratch =
      fs::temp_directory_path() / ("prism_docs_links_" + std::to_string(::getpid()));
  fs::remove_all(scratch);
  fs::create_directories(scratch / "repo" / "docs");
  fs::create_directories(scratch / "shared");
  fs::create_directories(scratch / "repo-copy");
  std::ofstream(scratch / "repo" / "README.md") << "# Repo\n";
  std::ofstream(scratch / "repo" / "docs" / "a.md") << "# A\n\n## Scene files\n";
  std::ofstream(scratch / "shared" / "SPEC.md") << "# Spec\n";
  std::ofstream(scratch / "repo-copy" / "README.md") << "# Copy\n";
  const fs::path base = fs::canonical(scratch / "repo");
  const fs::path readme = base / "README.md";
  auto verdict = [&](const std::string& target) { return problemWith({readme, 1, target}, base); };
  EXPECT_EQ(verdict("docs/a.md"), "");
  EXPECT_EQ(verdict("docs/a.md#scene-files"), "");
  EXPECT_EQ(verdict("#repo"), "");
  EXPECT_EQ(verdict("https://example.org/x"), "");
  // The file exists, but outside the repository: broken in every clone.
  EXPECT_NE(verdict("../shared/SPEC.md").find("outside"), std::string::npos);
  // A sibling folder whose name starts like the root's is still outside.
  EXPECT_NE(verdict("../repo-copy/README.md").find("outside"), std::string::npos);
  EXPECT_NE(verdict("docs/no-such-file.md").find("no such file"), std::string::npos);
  EXPECT_NE(verdict("docs/a.md#no-such-heading").find("no heading"), std::string::npos);
  EXPECT_NE(verdict("file:///etc/passwd"), "");
  fs::remove_all(scratch);
}

TEST(DocsLinks, EveryLinkResolvesInsideTheRepository) {
  for (const fs::path& doc : documents()) {
    const std::vector<Link> links = linksOf(doc);
    // The README has a picture and links to every document: finding fewer
    // than ten would mean the parser stopped seeing them.
    if (doc == root() / "README.md") {
      EXPECT_GE(links.size(), 10u);
    }
    for (const Link& link : links)
      EXPECT_EQ(problemWith(link), "") << where(link);
  }
}

TEST(DocsLinks, NothingPointsAtTheSharedFolderOrTheSpecification) {
  // The README once sent readers to ../shared/SPEC.md, which is not part of
  // any clone. The documents say what Prism does in their own words and
  // never send a reader outside, not even in a code span or a sentence.
  for (const fs::path& doc : documents()) {
    const std::vector<std::string> lines = linesOf(slurp(doc));
    for (std::size_t i = 0; i < lines.size(); ++i) {
      for (const char* forbidden : {"../shared", "SPEC.md"})
        EXPECT_EQ(lines[i].find(forbidden), std::string::npos)
            << fs::relative(doc, root()).string() << ":" << i + 1 << ": mentions " << forbidden;
    }
  }
}

TEST(DocsLinks, NoDocumentKeepsAMergeConflict) {
  // A merge once left both sides of a conflict, markers and all, in
  // docs/layout.md; links still resolved, so nothing else noticed.
  for (const fs::path& doc : documents()) {
    const std::vector<std::string> lines = linesOf(slurp(doc));
    for (std::size_t i = 0; i < lines.size(); ++i)
      for (const char* marker : {"<<<<<<< ", ">>>>>>> ", "|||||||"})
        EXPECT_NE(lines[i].rfind(marker, 0), 0u)
            << fs::relative(doc, root()).string() << ":" << i + 1 << ": a conflict marker";
  }
}

TEST(DocsLinks, TheReadmeLinksEveryDocument) {
  // README's "Where to read on" is how a newcomer finds the documents: one
  // that no README link reaches is as good as lost.
  std::set<fs::path> linked;
  for (const Link& link : linksOf(root() / "README.md")) {
    if (isExternal(link.target)) continue;
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(
        root() / percentDecoded(link.target.substr(0, link.target.find('#'))), ec);
    if (!ec) linked.insert(p);
  }
  for (const fs::path& doc : documents()) {
    if (doc.filename() == "README.md" && doc.parent_path() == root()) continue;
    EXPECT_TRUE(linked.count(doc))
        << "README.md does not link " << fs::relative(doc, root()).string();
  }
}

} // namespace
