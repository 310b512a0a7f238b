//
// Label.cc : formats a sensor label and parses it back.
//
// Only <string> is included: with gcc 3.3 it brought <cstring>, <cstdlib>,
// <climits> and <cstdio> along, so memcpy, abs, INT_MAX, sprintf and
// std::strlen needed no header of their own, and newlib's <string.h> had
// strlwr. gcc 4.3 stopped that; glibc never had strlwr.
//
// Parse calls a member template of a dependent type without "template"
// ("reader.As<int>(s)"): gcc 3.3 accepted it, gcc 3.4 requires
// "reader.template As<int>(s)". "template Span<int>;" instantiates a class
// template explicitly without "class", which gcc 3.4 requires too.
//
#include <string>

std::string
MakeLabel(const char* part, int value)
{
    char buf[32];
    memcpy(buf, part, 4);
    buf[4] = '\0';
    sprintf(buf + 4, "-%d", abs(value));
    return std::string(strlwr(buf));
}

struct Fields {
    template <class T> T As(const char* s) const { return (T)atoi(s); }
};

template <class Reader>
int
Parse(const Reader& reader, const char* s)
{
    return reader.As<int>(s);
}

template <class T>
struct Span {
    T from, to;
    T Length() const { return to - from; }
};
template Span<int>;

int
LabelValue(const std::string& label)
{
    const char* dash = strchr(label.c_str(), '-');
    if (dash == 0 || std::strlen(dash) < 2) return INT_MAX;
    Span<int> digits = { 0, (int)std::strlen(dash + 1) };
    return digits.Length() > 0 ? Parse(Fields(), dash + 1) : 0;
}
