// Captures OSG's notifications for the lifetime of a scope, so tests can check that clamping says so.
#pragma once
#include <osg/Notify>
#include <osg/ref_ptr>
#include <sstream>
#include <string>

struct WarnCapture : public osg::NotifyHandler {
    std::ostringstream text;
    void notify(osg::NotifySeverity, const char* message) override { text << message; }
};

struct ScopedWarnCapture {
    osg::ref_ptr<WarnCapture> capture = new WarnCapture;
    osg::ref_ptr<osg::NotifyHandler> previous = osg::getNotifyHandler();
    ScopedWarnCapture() { osg::setNotifyHandler(capture.get()); }
    ~ScopedWarnCapture() { osg::setNotifyHandler(previous.get()); }
    std::string str() const { return capture->text.str(); }
};
