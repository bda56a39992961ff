/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PHOTONGATHER
#define OSGWATER_PHOTONGATHER 1

#include <osgWater/WaterSettings>
#include <osg/Camera>
#include <osg/Geode>
#include <osg/Texture2D>
#include <map>
#include <tuple>

namespace osgWater {

class ProgramLibrary;

//! Caustics pass 3: gathers the photon target into the caustics texture (power per area seen from
//! the sun, in units of the sun's irradiance) by one of two methods (WaterSettings::CausticsMethod:
//! photons splatted, or the area-ratio mesh whose vertices they are), one of three ways
//! (WaterSettings::CausticsGather):
//!  - GATHER_POINTS_COPY: the photon target is copied into the vertex buffer of a point cloud
//!    through the pixel-pack binding (a pixel buffer object), then drawn as points (thesis §8.1);
//!  - GATHER_POINTS_TEXTURE: points that read the photon target in the vertex shader;
//!  - GATHER_CPU: read back, osgWater::splatPhotons or osgWater::meshPhotons, upload.
//! Points are tent splats with additive blending (shaders/splat.*), the same sums as the CPU; the
//! mesh's triangles likewise add their area-ratio irradiance.
class OSGWATER_EXPORT PhotonGather : public osg::Camera
{
public:
    //! `floatTarget` false: 16-bit unsigned normalised texture holding value / getValueScale().
    //! `waterState`: the water StateSet (waves, indices, Fresnel, extinction) the procedural path
    //! draws under.
    PhotonGather(osg::Texture2D* photons, ProgramLibrary& programs, int gridSize, int resolution, bool floatTarget,
                 osg::StateSet* waterState = nullptr);
    //! This frame's sun for CAUSTICS_PROCEDURAL, which gathers no photons: each texel's bed point,
    //! from the sun's depth map (`sunDepth`, the underwater scene) through `texToLocal` (sun texture
    //! space (u, v, depth) -> water-local), is traced back to the waves (shaders/procedural.frag).
    //! `sunView` (water-local -> sun eye space), `shade` and its projection: what stands above the
    //! water (a texel whose water the sun cannot reach is dark, as a photon there would be).
    void setProceduralSun(const osg::Matrixd& texToLocal, const osg::Matrixd& sunView, const osg::Vec3& towardsSun,
                          osg::Texture2D* sunDepth, osg::Texture2D* shade, const osg::Matrixd& shadeProjection);

    //! One of the three gather paths for a method, as CausticsCamera::resolveGather() chose it
    //! (GATHER_AUTO: none), drawn once or, `supersampled`, four times shifted by a quarter texel
    //! each way with a quarter of the energy (kSupersampleShifts), and `tiled`, nine times as many,
    //! moved by a whole texture each way (gatherPasses()). A path is made the first time it is chosen.
    void setMethod(WaterSettings::CausticsGather gather, WaterSettings::CausticsMethod method, bool supersampled,
                   bool tiled = false);
    WaterSettings::CausticsGather getMethod() const { return _method; }
    WaterSettings::CausticsMethod getCausticsMethod() const { return _causticsMethod; }
    bool getSupersampled() const { return _supersampled; }
    bool getTiled() const { return _tiled; }

    //! The caustics texture, with its mipmaps made after every draw.
    osg::Texture2D* getCausticsTexture() const { return _caustics.get(); }
    //! Stored texel = caustic value / scale (1 for float targets).
    float getValueScale() const { return _valueScale; }
    int getResolution() const { return _resolution; }

protected:
    virtual ~PhotonGather() {}
    using PathKey = std::tuple<WaterSettings::CausticsGather, WaterSettings::CausticsMethod, bool, bool>;
    osg::Group* makePath(const PathKey& key);

    WaterSettings::CausticsGather _method;
    WaterSettings::CausticsMethod _causticsMethod;
    bool _supersampled = false, _tiled = false;
    int _grid, _resolution;
    float _valueScale;
    osg::ref_ptr<osg::Texture2D> _photons, _caustics;
    osg::StateSet* _waterState;                // owned by the WaterNode, which outlives its cameras
    osg::ref_ptr<osg::StateSet> _proceduralState;
    std::map<PathKey, osg::ref_ptr<osg::Group>> _paths; // the paths chosen so far
};

}

#endif
