// Figures through gnuplot (Debian's gnuplot-nox): a data file and a script written next to the
// figure, run, and removed.
#pragma once
#include <string>

namespace bench {

//! Writes `data` to dir/stem.dat and `commands` to dir/stem.gp (the script names its data file
//! with the placeholder DATA and its output as dir/stem.png through OUTPUT), runs gnuplot and
//! removes both files. True when gnuplot succeeded.
bool runGnuplot(const std::string& dir, const std::string& stem, const std::string& data, std::string commands);

}
