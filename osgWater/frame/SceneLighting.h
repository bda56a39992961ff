/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SCENELIGHTING
#define OSGWATER_SCENELIGHTING 1

#include <osgWater/Export>
#include <osg/Matrixd>
#include <osg/Plane>
#include <osg/StateSet>
#include <osg/Texture2D>
#include <osgWater/WaterSettings>

namespace osgWater {

//! The caustics of this frame as the scene shader applies them (see shaders/caustics.glsl).
struct OSGWATER_EXPORT CausticsLighting {
    osg::Matrixd localToSun;      //!< water-local frame -> the sun camera's texture space [0,1]^3
    float intensity = 1.0f;       //!< scale of the caustics texture's values
    osg::Vec2f depthBias;         //!< sun depth-map bias: constant, per unit of slope tangent
    //! The photons carry one energy, faded by the green channel's sun extinction; the others differ
    //! by exp(-channelExtinction * depth below the level) (the refracted sun's path, level water);
    //! a tile's photons are not faded: its channelExtinction is the whole extinction
    osg::Vec3f channelExtinction;
    osg::ref_ptr<osg::Texture2D> caustics, depth;
    //! Tileable caustics: the texture holds one tile, looked up at localToTile (water-local -> tile
    //! units, the texture wrapping), the depth map still at localToSun
    bool tiled = false;
    osg::Matrixd localToTile;
    //! Procedural caustics made per fragment (CAUSTICS_PROCEDURAL_SCREEN): no caustics texture; the
    //! sun's shade map (or none) with its projection, and the sun camera's view (water-local -> its
    //! eye space), for the shade test at the point where a bed point's backward ray leaves the water
    bool procedural = false;
    osg::ref_ptr<osg::Texture2D> shade;
    osg::Matrixd sunView, shadeProjection;
};

//! Everything the scene program (shaders/scene.*) needs besides the scene's own state, for one
//! pass: built once per view and frame by WaterNode and applied to every pass that draws the
//! WaterNode's children (reflection, refraction, the sun's depth, the view itself, also with the
//! water out of view), each in its own eye space. Values in the water's local frame.
struct OSGWATER_EXPORT SceneLighting {
    osg::Vec3 towardsSun = osg::Vec3(0.0f, 0.0f, 1.0f);
    osg::Vec3 fogColor;          //!< eq. 10: fragments blend towards this colour ...
    osg::Vec3 fogExtinction;     //!< ... by exp(-k |fragment - pass eye|) per channel; 0: the pass's eye is not in water
    double level = 0.0;          //!< the mean water plane z = level (caustics apply below it)
    const CausticsLighting* caustics = nullptr; //!< null: no caustics this frame
    //! The reflective caustics (the sun reflected off the water onto what stands above it; their
    //! localToSun mirrors a fragment in the water plane first), or null.
    const CausticsLighting* reflectedCaustics = nullptr;
    bool clip = false;           //!< clip to keepPlane (gl_ClipDistance[0]); the view itself does not clip
    bool display = false;        //!< the view itself: its colour is encoded for display (OSGWATER_DISPLAY);
                                 //!< a pass's target holds linear light
    osg::Plane keepPlane;        //!< a x + b y + c z + d >= 0 is kept
};

//! Points `ss` (a pass's DYNAMIC StateSet) at `lighting` for a pass whose view matrix (water-local
//! frame -> the pass's eye space) is `view`: uniforms, the caustics and sun-depth textures on their
//! units, the clip distance mode. Creates what it sets on first use.
OSGWATER_EXPORT void applySceneLighting(osg::StateSet* ss, const SceneLighting& lighting, const osg::Matrixd& view);

//! Points `ss` at the sun's shade map as shaders/sunshade.glsl reads it: the map on texture unit
//! `unit` (its sampler), its projection and that projection's inverse. The photon pass, the
//! procedural caustics' texture pass and the scene program (procedural caustics per pixel) alike.
OSGWATER_EXPORT void applySunShade(osg::StateSet* ss, osg::Texture2D* shade, int unit, const osg::Matrixd& projection);

//! The photons' energy fades with the green channel's sun extinction (what the photon pass uses).
OSGWATER_EXPORT float photonExtinction(const WaterSettings& s);
//! Per channel, the sun extinction beyond the photons' along the refracted sun's path per metre of
//! depth: (K - K_green) / cos(refracted sun angle). Zero for the thesis model. `whole`: K / cos,
//! for photons that carry no fade of their own (tileable caustics).
OSGWATER_EXPORT osg::Vec3f channelExtinction(const WaterSettings& s, bool whole = false);

//! Sets the uniform `name` of `ss` to `value`, adding it the first time.
template <class T> void setOrAddUniform(osg::StateSet* ss, const char* name, const T& value)
{
    if (osg::Uniform* u = ss->getUniform(name)) u->set(value);
    else ss->addUniform(new osg::Uniform(name, value));
}
//! Sets the shader define `name` on `ss` when `on`, removes it otherwise.
OSGWATER_EXPORT void setDefineIf(osg::StateSet* ss, const char* name, bool on);

}

#endif
