/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_GLOWBANDS
#define OSGWATER_GLOWBANDS 1

#include <osgWater/Export>
#include <osg/Geometry>
#include <osg/buffered_value>
#include <atomic>

namespace osgWater {

//! The glow's composite drawn only in the horizontal bands of the view that the blurred glow
//! reaches. The last blur pass draws its target as the same bands, each under an occlusion query,
//! its texels below the visible cut discarded (left at the cleared zero); the composite draws each
//! band under GL's conditional rendering on that band's query, so the GPU itself skips a band
//! without glow, in the same frame, and the CPU never waits for a result. Where GL has no
//! conditional rendering (before GL 3.0) every band is drawn, and that is said once.
class OSGWATER_EXPORT GlowBands : public osg::Referenced
{
public:
    //! Bands per view: each costs a query and two draws; fewer, larger bands skip less.
    static constexpr int BANDS = 8;
    //! Texel rows each query band reaches beyond its composite band: what bilinear filtering reads.
    static constexpr int MARGIN = 2;

    GlowBands();

    //! The last blur pass's quads over a target of `height` rows (NDC), each counted by its query.
    osg::Geometry* makeCountedBands(int height);
    //! The composite's quads over the view (NDC, at depth z), each drawn if its band was counted.
    osg::Geometry* makeConditionalBands(float z);

    //! Off, the composite draws every band and nothing is counted (skipping off: the full frame).
    void setEnabled(bool on) { _enabled = on; }
    bool getEnabled() const { return _enabled.load(); }

    //! The band drawing's GL calls, per context (the primitive sets' draws call them). The begins
    //! return whether they began (off, no support, or for the composite a band never counted:
    //! drawn plainly), and an end follows only a begin that did.
    bool beginCount(osg::State& state, int band);
    void endCount(osg::State& state);
    bool beginConditional(osg::State& state, int band);
    void endConditional(osg::State& state);

    void releaseGLObjects(osg::State* state) const;

protected:
    virtual ~GlowBands();
    struct PerContext {
        unsigned int ids[BANDS] = {};
        bool counted[BANDS] = {};
        int support = 0; // 0 unknown, 1 queries and conditional rendering, 2 neither
        void (*beginConditionalRender)(unsigned int, unsigned int) = nullptr;
        void (*endConditionalRender)() = nullptr;
    };
    bool ready(osg::State& state, PerContext& c);
    std::atomic<bool> _enabled{ true };
    mutable osg::buffered_object<PerContext> _contexts;
};

}

#endif
