// What a run has finished, kept on disk so that a run cut short goes on where it stopped: each
// technique's records and summary, and the ablation, written as each finishes. A file is used
// again only by a run with the same key: the caller's (scripts/bench.sh: the sources' git trees, so
// a change to the library, the shaders, the apps or the data measures everything afresh) joined
// with every option that changes a figure.
#pragma once
#include "Ablation.h"
#include "BenchOptions.h"
#include "Report.h"
#include <string>
#include <vector>

namespace bench {

class ResumeCache
{
public:
    //! Files under `dir`; an empty `sourceKey` keeps and reads nothing.
    ResumeCache(const std::string& dir, const std::string& sourceKey, const BenchOptions& options);

    bool enabled() const { return !_key.empty(); }
    //! A finished technique's records (in view order) and summary; false when none was kept under this key.
    bool loadTechnique(const std::string& technique, std::vector<Record>& records, Summary& summary) const;
    bool saveTechnique(const std::string& technique, const std::vector<Record>& records, const Summary& summary,
                       std::string& error) const;
    //! The ablation's timings; its configurations are ablationConfigs().
    bool loadAblation(Ablation& ablation) const;
    bool saveAblation(const Ablation& ablation, std::string& error) const;

private:
    std::string file(const std::string& name) const;
    std::string _dir, _key;
};

}
