#pragma once
// Enum-valued options: the words a user may type and the enum value each stands for, in one table
// that the parser, the help text and the error message all read.
#include <string>
#include <vector>

namespace aurorawall::cli {

template <class E>
struct Choice {
    const char* word;
    E value;
};

template <class E>
using Choices = std::vector<Choice<E>>;

// "egl, osmesa, glfw"
template <class E>
std::string wordsOf(const Choices<E>& choices)
{
    std::string words;
    for (const Choice<E>& c : choices)
        words += (words.empty() ? "" : ", ") + std::string(c.word);
    return words;
}

// The word of a value ("" if the table lacks it).
template <class E>
std::string wordOf(const Choices<E>& choices, E value)
{
    for (const Choice<E>& c : choices)
        if (c.value == value)
            return c.word;
    return "";
}

// The value of a word; false if the word is not in the table.
template <class E>
bool findChoice(const Choices<E>& choices, const std::string& word, E& value)
{
    for (const Choice<E>& c : choices)
        if (word == c.word) {
            value = c.value;
            return true;
        }
    return false;
}

} // namespace aurorawall::cli
