#include "console/experiments/figure_index.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <ostream>

#include "robot/core/output_file.hpp"

namespace stride::experiments {

namespace {

namespace fs = std::filesystem;

// Text and attribute values in the page: the five characters HTML gives a meaning.
std::string escaped(const std::string& s) {
  std::string r;
  for (const char c : s) {
    switch (c) {
      case '&':
        r += "&amp;";
        break;
      case '<':
        r += "&lt;";
        break;
      case '>':
        r += "&gt;";
        break;
      case '"':
        r += "&quot;";
        break;
      case '\'':
        r += "&#39;";
        break;
      default:
        r += c;
    }
  }
  return r;
}

// A relative path as a URL path: each character outside the unreserved set percent-encoded.
std::string url_path(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string r;
  for (const char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '/' || c == '.' || c == '_' || c == '-' || c == '~') {
      r += c;
    } else {
      r += '%';
      r += hex[u >> 4];
      r += hex[u & 15];
    }
  }
  return r;
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1em}h2{margin-top:1.5em;border-bottom:1px solid #ccc}"
    "figure{display:inline-block;margin:0 .6em .8em 0;vertical-align:top}"
    "figure img{width:360px;border:1px solid #ddd}figcaption{font-size:.8em;max-width:360px}";

}  // namespace

std::vector<FigureFamily> figure_families(const std::string& out_dir) {
  std::map<std::string, std::vector<std::string>> by_folder;
  std::error_code ec;
  const fs::path root(out_dir);
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec) || it->path().extension() != ".png") continue;
    const std::string folder = it->path().parent_path().lexically_relative(root).generic_string();
    by_folder[folder].push_back(it->path().filename().string());
  }
  std::vector<FigureFamily> families;
  for (auto& [folder, pictures] : by_folder) {  // "." sorts before any folder name
    std::sort(pictures.begin(), pictures.end());
    families.push_back({folder, std::move(pictures)});
  }
  return families;
}

std::string write_figure_index(const std::string& out_dir, const std::string& title) {
  const std::vector<FigureFamily> families = figure_families(out_dir);
  if (families.empty()) return "";
  std::size_t count = 0;
  for (const FigureFamily& f : families) count += f.pictures.size();
  std::string page = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" +
                     escaped(title) + "</title><style>" + kStyle + "</style></head><body>\n<h1>" +
                     escaped(title) + "</h1>\n<p>" + std::to_string(count) + " figures in " +
                     std::to_string(families.size()) +
                     " folders; each picture's gnuplot script (.gp) lies beside it.</p>\n";
  for (const FigureFamily& f : families) {
    const std::string prefix = f.folder == "." ? "" : f.folder + "/";
    page += "<h2>" + escaped(f.folder == "." ? "top folder" : f.folder) + "</h2>\n";
    for (const std::string& p : f.pictures) {
      const std::string href = escaped(url_path(prefix + p));
      page += "<figure><a href=\"" + href + "\"><img src=\"" + href + "\" alt=\"" +
              escaped(prefix + p) + "\" loading=\"lazy\"></a><figcaption>" + escaped(p) +
              "</figcaption></figure>\n";
    }
  }
  page += "</body></html>\n";
  const std::string path = (fs::path(out_dir) / "index.html").string();
  write_file(path, page);
  return path;
}

void print_figure_index(const std::string& out_dir, const std::string& experiment,
                        std::ostream& out) {
  const std::string page = write_figure_index(out_dir, "stride experiment " + experiment);
  if (page.empty()) return;
  std::size_t count = 0;
  for (const FigureFamily& f : figure_families(out_dir)) count += f.pictures.size();
  out << "figures: " << page << " (" << count << " figures, one section per folder)\n";
}

}  // namespace stride::experiments
