#include "places/query_forms.hpp"

#include <algorithm>
#include <string_view>

namespace globe::places {
namespace {

struct WordForm {
  std::string_view typed;
  std::string_view inNames;
};

// Each pair is tried both ways: names hold both "St. Louis" and "Saint-Étienne".
constexpr WordForm kWordForms[] = {
    {"mt", "mount"},   {"mtn", "mountain"},  {"mtns", "mountains"},   {"st", "saint"},
    {"ste", "sainte"}, {"ft", "fort"},       {"pt", "point"},         {"pk", "peak"},
    {"lk", "lake"},    {"natl", "national"}, {"np", "national park"}, {"n", "north"},
    {"s", "south"},    {"e", "east"},        {"w", "west"},           {"mt", "mont"},
    {"mt", "monte"},   {"sta", "santa"},     {"sto", "santo"},        {"st", "sankt"},
};

// Umlauts written out, as German and Swiss names are typed without them.
constexpr WordForm kLetterForms[] = {{"ue", "u"}, {"oe", "o"}, {"ae", "a"}};

std::vector<std::string> splitWords(const std::string& text) {
  std::vector<std::string> words;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(' ', start), text.size());
    if (end > start) words.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

std::vector<std::string> wordAlternatives(const std::string& word) {
  std::vector<std::string> alternatives{word};
  for (const WordForm& f : kWordForms) {
    if (word == f.typed) alternatives.emplace_back(f.inNames);
    if (word == f.inNames) alternatives.emplace_back(f.typed);
  }
  return alternatives;
}

void addForm(std::vector<std::string>& forms, std::string form) {
  if (forms.size() < kMaxQueryForms && std::find(forms.begin(), forms.end(), form) == forms.end())
    forms.push_back(std::move(form));
}

std::string replacedAll(std::string text, std::string_view from, std::string_view to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

std::vector<std::string> queryForms(const std::string& foldedQuery) {
  // Every combination of the words' alternatives, the typed words first.
  std::vector<std::string> forms{""};
  for (const std::string& word : splitWords(foldedQuery)) {
    std::vector<std::string> longer;
    for (const std::string& start : forms) {
      for (const std::string& alternative : wordAlternatives(word)) {
        if (longer.size() < kMaxQueryForms)
          longer.push_back(start.empty() ? alternative : start + " " + alternative);
      }
    }
    forms = std::move(longer);
  }
  std::vector<std::string> unique;
  addForm(unique, foldedQuery);
  for (std::string& form : forms) addForm(unique, std::move(form));
  const size_t wordForms = unique.size();
  for (size_t i = 0; i < wordForms; ++i) {
    std::string plain = unique[i];
    for (const WordForm& f : kLetterForms) plain = replacedAll(plain, f.typed, f.inNames);
    addForm(unique, std::move(plain));
  }
  return unique;
}

}  // namespace globe::places
