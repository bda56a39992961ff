#include "serialize/FieldSerializers.h"
#include <osg/Math>
#include <cstdio>

namespace osgWater {
namespace detail {

namespace {

// what the reader parses with: floats as osgDB does, doubles exactly
double readBack(const char* text, float) { return osg::asciiToDouble(text); }
double readBack(const char* text, double)
{
    double v = 0.0;
    std::string why;
    parseToken(text, v, why);
    return v;
}

template <typename T> int shortest(T v, int most)
{
    char text[64];
    for (int digits = 6; digits < most; ++digits) {
        std::snprintf(text, sizeof(text), "%.*g", digits, double(v));
        if (T(readBack(text, v)) == v) return digits;
    }
    return most;
}

int slot()
{
    static const int index = std::ios_base::xalloc();
    return index;
}

template <int D> std::ostream& setDigits(std::ostream& s)
{
    s.iword(slot()) = long(s.precision(D));
    return s;
}

}

int digitsFor(float v) { return shortest(v, 9); }
int digitsFor(double v) { return shortest(v, 17); }

Manipulator setPrecision(int digits)
{
    static const Manipulator table[] = { setDigits<6>, setDigits<7>, setDigits<8>, setDigits<9>,
                                         setDigits<10>, setDigits<11>, setDigits<12>, setDigits<13>,
                                         setDigits<14>, setDigits<15>, setDigits<16>, setDigits<17> };
    return table[std::min(std::max(digits, 6), 17) - 6];
}

std::ostream& restorePrecision(std::ostream& s)
{
    s.precision(std::streamsize(s.iword(slot())));
    return s;
}

}
}
