/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PHOTONCAMERA
#define OSGWATER_PHOTONCAMERA 1

#include <osgWater/Export>
#include "frame/DrawNodes.h"
#include <osg/Camera>
#include <osg/Texture2D>

namespace osgWater {

class ProgramLibrary;

//! Caustics pass 2 (thesis §8.1, §9.2): the water surface seen from the sun's orthographic camera,
//! one photon per texel: (u, v, energy, 1) where the refracted sun ray meets the bed, found in the
//! sun's depth map (shaders/photon.frag). Renders into a float RGBA target (16-bit unsigned
//! normalised where the context has no float targets).
class OSGWATER_EXPORT PhotonCamera : public osg::Camera
{
public:
    //! `waterState`: the water StateSet (waves, indices, Fresnel, attenuation), pushed under the
    //! photon program.
    PhotonCamera(osg::StateSet* waterState, ProgramLibrary& programs, int gridSize, bool floatTarget);

    //! The surface to draw, the sun's view and projection, and its depth map (pass 1). With
    //! `mirror` (the mirror in the water plane, water-local frame), the photons are the sun's
    //! reflection (reflective caustics): each reflected ray is mirrored in the water plane and
    //! searched in a depth map of the scene above the water mirrored the same way, its energy F.
    void setSun(osg::Node* surface, const osg::Matrixd& view, const osg::Matrixd& projection,
                osg::Texture2D* sunDepth, const osg::Matrixd* mirror = nullptr);
    //! What shades the water from the sun (setSun() without a mirror): a depth map of the whole
    //! scene in the sun's view, its projection. A photon whose water lies behind it is dark.
    void setSunShade(osg::Texture2D* shade, const osg::Matrixd& projection);
    //! Tileable caustics instead: the surface seen straight down over one tile (`view`,
    //! `projection`), each refracted sun ray meeting the flat bed z = bedZ (water-local frame),
    //! its photon's (u, v) in tile units: `localToTile` (water-local -> tile).
    void setTile(osg::Node* surface, const osg::Matrixd& view, const osg::Matrixd& projection,
                 const osg::Vec3& towardsSun, double bedZ, const osg::Matrixd& localToTile);

    //! An empty pass draws nothing and clears nothing (the procedural caustics need no photons; the
    //! pass only starts the caustics' GPU timer). Set after setSun(), which draws the surface again.
    void setEmpty(bool empty);
    bool isEmpty() const { return _empty; }
    osg::Texture2D* getPhotonTexture() const { return _photons.get(); }
    int getGridSize() const { return _size; }
    osg::Node* getSurface() const { return _surface.get(); }
    osg::StateSet* getWaterState() const { return _waterState; }
    osg::StateSet* getPhotonState() const { return _photonState.get(); }

protected:
    virtual ~PhotonCamera() {}
    int _size;
    bool _empty = false;
    osg::StateSet* _waterState;         // owned by the WaterNode, which outlives its cameras
    osg::ref_ptr<osg::Node> _surface;
    osg::ref_ptr<osg::StateSet> _photonState;
    osg::ref_ptr<osg::Texture2D> _photons;
    osg::ref_ptr<DrawNodes> _draw;
};

}

#endif
