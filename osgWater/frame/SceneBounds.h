/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SCENEBOUNDS
#define OSGWATER_SCENEBOUNDS 1

#include <osgWater/Export>
#include <osg/BoundingBox>
#include <osg/Group>
#include <osg/Vec3>

namespace osgWater {

//! Where sunlight can enter the water and land: rays along the sun's direction, one per cell of
//! a `cells` x `cells` grid over the water's extent at the crest height. A ray lights the water
//! when the first geometry it meets lies below the crests. Above the crests only triangles that
//! face the sun shade the water (a shore, a pier's deck, the ground over a sky dome's lower half;
//! not the inside of the dome, whose triangles face away). The box's x, y
//! bound the crest-height entry points of the lit rays, grown by a cell; its zMin is the deepest
//! first hit of a lit ray, lowered by a quarter of the depth because refracted rays are steeper
//! than the sun's; its zMax the crest. Empty when no ray lights the water. Geometry counts by its
//! triangles, in the frame of the group's parent (the water's local frame for a WaterNode).
//! The same rays give the mean height of the bed where light lands (the lit rays' first hits) and
//! of what shades the water (the other rays' first hits above the crests): where the plane-offset
//! lookups put the scene when their planes are not set.
struct LitWater {
    osg::BoundingBox box;          //!< as above; invalid when no ray lights the water
    double meanBedZ = 0.0;         //!< mean height of the lit rays' first hits (valid with box)
    double meanShadeZ = 0.0;       //!< mean height of the first hits above the crests
    bool shaded = false;           //!< whether any ray met something above the crests
};
OSGWATER_EXPORT LitWater findLitWater(osg::Group& scene, const osg::BoundingBox& water, double crest,
                                      const osg::Vec3& towardsSun, int cells = 128);

//! The children's boxes of a group, cached: the whole box, and the lit water (findLitWater()).
//! The whole box is recomputed when the group's bounding sphere changes, the lit water's also
//! when the water's box, the crest or the sun changes (it walks every triangle: milliseconds for
//! a scene of 100 000).
class OSGWATER_EXPORT SceneBoxes
{
public:
    //! `lit` false: the lit water is not needed (not walked; an empty one kept).
    void update(osg::Group& group, const osg::BoundingSphere& groupBound, const osg::BoundingBox& water,
                double crest, const osg::Vec3& towardsSun, bool lit = true);
    const osg::BoundingBox& whole() const { return _whole; }
    const LitWater& litWater() const { return _lit; }

private:
    osg::BoundingSphere _key;
    osg::BoundingBox _waterKey;
    double _crest = 0.0;
    osg::Vec3 _sun;
    bool _litValid = false;
    osg::BoundingBox _whole;
    LitWater _lit;
};

}

#endif
