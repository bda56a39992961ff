// Today's date as the generated documents print it.
#pragma once
#include <ctime>
#include <string>

namespace osgWaterApps {

//! Local date, YYYY-MM-DD.
inline std::string today()
{
    const std::time_t now = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d", std::localtime(&now));
    return buf;
}

}
