/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PASSMATH
#define OSGWATER_PASSMATH 1

#include <osgWater/Export>
#include <osg/Matrixd>
#include <osg/Plane>
#include <osg/Vec2i>
#include <osg/BoundingSphere>
#include <osg/BoundingBox>
#include <vector>

//! Matrix maths of the render-to-texture passes, as free functions so tests run without a GPU.
//! Conventions are OSG's: row vectors (v' = v * M), view matrices map the water's local frame
//! (z up, water plane z = level) to eye space.
namespace osgWater {

//! Reflection about the plane z = level: (x, y, z) -> (x, y, 2 level - z).
OSGWATER_EXPORT osg::Matrixd mirrorMatrix(double level);

//! A projection whose visible tangent range is `ext` times wider in x and y
//! (thesis §5.2); texture coordinates of the pass come from this same matrix.
OSGWATER_EXPORT osg::Matrixd extendFov(const osg::Matrixd& projection, double ext);

//! Replaces near/far of a perspective or orthographic projection, keeping its field of view.
OSGWATER_EXPORT osg::Matrixd withNearFar(const osg::Matrixd& projection, double zNear, double zFar);

//! Lengths in the eye space of `view` of the water's local x, y and z unit vectors: (1, 1, 1)
//! unless a transform above the WaterNode scales.
OSGWATER_EXPORT osg::Vec3d axisScales(const osg::Matrixd& view);
//! Length in the water's local frame of a unit length in the eye space of `view` (1 unless the
//! WaterNode is under a scale): near/far, fog and attenuation count local metres with it.
OSGWATER_EXPORT double localLengthPerEyeLength(const osg::Matrixd& view);

//! Near/far that enclose `bound` (in the view's local frame) for the given view matrix;
//! returns false when the bound lies wholly behind the eye.
OSGWATER_EXPORT bool nearFarForBound(const osg::Matrixd& view, const osg::BoundingSphere& bound,
                                     double& zNear, double& zFar);

//! Thesis §5.1 eq. 1-2: the view matrix of the refraction camera, the main camera rotated about
//! O (where the bottom-centre ray of the view frustum meets the water) by the angle between that
//! ray and its refraction. Returns `view` unchanged when the ray points at the sky. An eye at or
//! below `level` (in a trough: still in the air) rotates about itself, so the camera changes
//! continuously as the eye comes down to the water (the caller does not call it under water).
//! `distanceScale`: the turned camera's distance from O over the eye's, along the refracted ray (1:
//! the thesis's rigid rotation; 1 / eta: the eye where it appears to be seen from under the water,
//! the paraxial apparent height, so that the pass's straight rays under the water lie closer to the
//! refracted rays and see less of the bed from the wrong side of an edge).
OSGWATER_EXPORT osg::Matrixd rotatedRefractionView(const osg::Matrixd& view, const osg::Matrixd& projection,
                                                   double level, double eta, double distanceScale = 1.0);

//! The plane `localPlane` (a x + b y + c z + d >= 0 is kept) expressed in the eye space of `view`,
//! ready for gl_ClipDistance = dot(plane, eyePosition).
OSGWATER_EXPORT osg::Vec4d planeToEye(const osg::Vec4d& localPlane, const osg::Matrixd& view);

//! Eye position in the local frame of a view matrix.
OSGWATER_EXPORT osg::Vec3d eyePosition(const osg::Matrixd& view);

//! Texture coordinate (and depth, in [0,1]) of a local point in a pass with this view and projection.
OSGWATER_EXPORT osg::Vec3d projectToTexture(const osg::Vec3d& local, const osg::Matrixd& view,
                                            const osg::Matrixd& projection);

//! The sun's orthographic camera (thesis ch. 8, fig. 17): a view looking along -towardsSun at the
//! centre of `box`, from outside it; its up axis is local +y made perpendicular to the sun (local
//! +x when the sun lies along y), so an overhead sun gives image axes x, y.
OSGWATER_EXPORT osg::Matrixd sunView(const osg::Vec3d& towardsSun, const osg::BoundingBox& box);
//! The tightest orthographic projection of `box` under `view` (all eight corners inside).
OSGWATER_EXPORT osg::Matrixd sunProjection(const osg::Matrixd& view, const osg::BoundingBox& box);
//! Maps clip space [-1,1] to texture space [0,1] in x, y and z (post-multiply a projection).
OSGWATER_EXPORT osg::Matrixd clipToTexture();

//! Whether any part of the box lies inside all the planes (inside = non-negative distance), by
//! clipping its faces: exact, where a plane-by-plane test keeps a box that reaches behind the eye
//! and below the frustum (a lake's box, seen from its shore looking at the sky).
OSGWATER_EXPORT bool boxInsidePlanes(const osg::BoundingBox& box, const std::vector<osg::Plane>& planes);

//! A pass target's size for a view `viewportWidth` x `viewportHeight`: that viewport scaled by
//! `scale` per axis (its aspect kept), each side 16..4096; or `fixedSize` square when `scale` is 0
//! or there is no viewport.
OSGWATER_EXPORT osg::Vec2i passTargetSize(double viewportWidth, double viewportHeight, double scale, int fixedSize);

//! Whether the near plane of `projection` can cut the surface away, seen through `modelView`
//! (water-local frame -> eye space): some point of the near-plane rectangle lies on the other
//! side of the wave band [level - waveBound, level + waveBound] than the eye, or within it, or
//! the eye is in the band. When it cannot, the near-plane cap would discard every pixel.
OSGWATER_EXPORT bool nearPlaneReachesWater(const osg::Matrixd& modelView, const osg::Matrixd& projection, double level,
                                           double waveBound);

//! A side count (texels, photons) for a window `ratio` times as wide as the one `count` was set
//! for, at the same spacing: count * ratio rounded up to a multiple of 8, kept within
//! [min(count, 32), count] (a window never grows past the set count; a tiny one keeps some detail).
OSGWATER_EXPORT int focusedCount(int count, double ratio);

}

#endif
