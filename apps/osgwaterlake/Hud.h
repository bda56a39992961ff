// A small on-screen text: frame rate, the passes' GPU times and the current water settings.
#pragma once
#include <osgWater/WaterNode>
#include <osg/Camera>

//! An orthographic nested camera holding the text; it refreshes itself every frame.
osg::ref_ptr<osg::Camera> createHud(osgWater::WaterNode* water, osg::Camera* mainCamera, int width, int height);
//! One line describing the settings (also printed by the headless run).
std::string describeSettings(const osgWater::WaterSettings& s);
//! The surface's mesh: its layout, or "mesh user".
std::string describeSurface(const osgWater::WaterSurface& s);
//! The caustics state: off, or the gather in use and the texture/photon-grid sizes.
std::string describeCaustics(const osgWater::WaterNode& water, const osgWater::ViewReport& report);
