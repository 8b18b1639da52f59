// doxygen_filter FILE: the input filter of the `doc` target (doc/doxygen/Doxyfile.in). Doxygen runs
// it on every input file and reads the file's text from its standard output.
//
// Markdown pages (*.md) are written for GitHub, whose links Doxygen 1.9 does not resolve:
// - every heading gets an explicit label, `{#<stem>_<slug>}` (the page's own title:
//   `{#page_<stem>}`), where <stem> is the file's stem and <slug> GitHub's anchor of the heading
//   with '-' turned into '_', so that the labels are unique across pages;
// - a link to a heading of the same page, `(#slug)`, or of another page of the reference,
//   `(other.md#slug)` or `(other.md)`, becomes a link to that label;
// - a link to a page outside the reference (the manual's chapters, the benchmarks) becomes plain
//   text naming the file, since the reference does not contain it.
// Headers (*.h) pass unchanged, except `\cond LABEL -- comment`, which Doxygen would parse as a
// section expression: the comment after the label is dropped.
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

/// The label of a page: its file's stem, prefixed so that it cannot clash with Doxygen's own pages
/// (concepts.html is Doxygen's list of C++ concepts).
std::string page_label(const fs::path& file) { return "page_" + file.stem().string(); }

/// The prefix of the labels of a page's sections: its file's stem.
std::string section_prefix(const fs::path& file) { return file.stem().string(); }

/// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to '-'; then '-' to '_'.
std::string slug(const std::string& heading)
{
    std::string out;
    for (const char c : heading) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u))
            out += char(std::tolower(u));
        else if (c == ' ' || c == '-')
            out += '_';
        else if (c == '_')
            out += '_';
        else if (u >= 0x80)
            out += c;  // UTF-8 letters stay, as on GitHub
    }
    std::string ascii;
    for (const char c : out)
        if (static_cast<unsigned char>(c) < 0x80) ascii += c;
    return ascii;
}

/// The reference's pages: the Markdown files Doxygen reads (see INPUT in Doxyfile.in).
bool in_reference(const fs::path& target, const fs::path& doc_dir)
{
    const fs::path t = target.lexically_normal();
    const fs::path rel = t.lexically_relative(doc_dir);
    const std::string r = rel.generic_string();
    return r == "algorithms.md" || r == "design.md" || r.rfind("reference/", 0) == 0 || r.rfind("doxygen/", 0) == 0;
}

std::string filter_markdown(const fs::path& file, std::istream& in)
{
    const fs::path dir = fs::absolute(file).parent_path();
    fs::path doc_dir = dir;
    while (!doc_dir.empty() && doc_dir.filename() != "doc" && doc_dir != doc_dir.root_path()) doc_dir = doc_dir.parent_path();
    const std::string page = page_label(file);
    static const std::regex heading(R"(^(#{1,6})\s+(.*?)\s*$)");
    static const std::regex link(R"(\[([^\]]*)\]\(([^)\s]*)\))");
    std::ostringstream out;
    bool in_code = false;
    bool first_heading = true;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("```", 0) == 0) in_code = !in_code;
        if (in_code) {
            out << line << '\n';
            continue;
        }
        std::smatch m;
        if (std::regex_match(line, m, heading) && line.find("{#") == std::string::npos) {
            const std::string label = first_heading ? page : section_prefix(file) + "_" + slug(m[2].str());
            first_heading = false;
            out << m[1].str() << ' ' << m[2].str() << " {#" << label << "}\n";
            continue;
        }
        std::string result;
        auto begin = line.cbegin();
        for (std::sregex_iterator it(line.begin(), line.end(), link), end; it != end; ++it) {
            const std::smatch& l = *it;
            result.append(begin, l[0].first);
            begin = l[0].second;
            const std::string text = l[1].str(), target = l[2].str();
            if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 ||
                (target.find(".md") == std::string::npos && target.front() != '#')) {
                result += l[0].str();  // external link, picture or source file: as is
                continue;
            }
            const std::size_t hash = target.find('#');
            const std::string path = target.substr(0, hash);
            const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
            const fs::path resolved = path.empty() ? fs::absolute(file) : (dir / path);
            if (!in_reference(resolved, doc_dir)) {
                result += text + " (doc/" + resolved.lexically_normal().lexically_relative(doc_dir).generic_string() + ")";
                continue;
            }
            std::string anchor_slug;
            for (const char c : anchor) anchor_slug += c == '-' ? '_' : c;
            result += "[" + text + "](#" +
                      (anchor.empty() ? page_label(resolved) : section_prefix(resolved) + "_" + anchor_slug) + ")";
        }
        result.append(begin, line.cend());
        out << result << '\n';
    }
    return out.str();
}

std::string filter_header(std::istream& in)
{
    static const std::regex cond(R"((\\cond\s+[A-Za-z_][A-Za-z0-9_]*)\s+--.*$)");
    std::ostringstream out;
    for (std::string line; std::getline(in, line);) out << std::regex_replace(line, cond, "$1") << '\n';
    return out.str();
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: doxygen_filter FILE\n";
        return 2;
    }
    const fs::path file = argv[1];
    std::ifstream in(file);
    if (!in) {
        std::cerr << "doxygen_filter: cannot open " << file << '\n';
        return 1;
    }
    std::cout << (file.extension() == ".md" ? filter_markdown(file, in) : filter_header(in));
    return 0;
}
