#include "analysis/dissertation/document_links.hpp"

#include <cctype>

namespace capsule::analysis {

std::string anchor_id(const std::string& kind, const std::string& name) {
  std::string id = kind;
  bool dash = true;  // a '-' separates the kind from the name
  for (const unsigned char c : name) {
    if (std::isalnum(c)) {
      if (dash) id += '-';
      id += static_cast<char>(std::tolower(c));
      dash = false;
    } else {
      dash = true;
    }
  }
  return id;
}

std::string claim_anchor(const std::string& claim_key) { return anchor_id("claim", claim_key); }
std::string cause_anchor(std::size_t number) { return std::string("cause-").append(std::to_string(number)); }
std::string cause_label(std::size_t number) { return std::string("C").append(std::to_string(number)); }

std::string markdown_link(const std::string& label, const std::string& target) {
  std::string link = "[";
  link.append(label).append("](").append(target).append(")");
  return link;
}

std::string anchor_link(const std::string& label, const std::string& id) {
  std::string target = "#";
  target.append(id);
  return markdown_link(label, target);
}

std::string claim_links(const std::vector<std::string>& keys) {
  std::string out;
  for (const auto& key : keys) append_listed(out, anchor_link(key, claim_anchor(key)));
  return out;
}

void append_listed(std::string& list, const std::string& item) {
  if (!list.empty()) list.append(", ");
  list.append(item);
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find(';', at);
    if (end == std::string::npos) end = text.size();
    std::size_t first = at, last = end;
    while (first < last && std::isspace(static_cast<unsigned char>(text[first]))) ++first;
    while (last > first && std::isspace(static_cast<unsigned char>(text[last - 1]))) --last;
    if (last > first) out.push_back(text.substr(first, last - first));
    at = end + 1;
  }
  return out;
}

}  // namespace capsule::analysis
