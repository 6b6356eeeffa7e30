// osgShadow on penumbra's generated grid scene, timed like `penumbra bench` times its frames:
// wall clock per frame after a warm-up, same window size, camera, sun direction and map size.
//   osgshadow_peer MODEL.obj --technique none|sm|ssm|pssm|lispsm --mapres N --size WxH
//                  --eye x,y,z --target x,y,z --fov DEG --sun x,y,z --frames N --warmup N --screenshot F.png
// Prints one line: "osgshadow <technique> ms_per_frame <mean> frames <N>".
#include <osg/LightSource>
#include <osg/Material>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgShadow/LightSpacePerspectiveShadowMap>
#include <osgShadow/ParallelSplitShadowMap>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowedScene>
#include <osgShadow/SoftShadowMap>
#include <osgViewer/Viewer>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

osg::Vec3 vec3(const char* text) {
    float x = 0, y = 0, z = 0;
    std::sscanf(text, "%f,%f,%f", &x, &y, &z);
    return {x, y, z};
}

// Grabs the final frame into an image (for checking by eye that both programs see the same view).
struct Capture : osg::Camera::DrawCallback {
    std::string file;
    mutable bool done = false;
    void operator()(osg::RenderInfo& info) const override {
        if (done || file.empty()) return;
        const osg::Viewport* vp = info.getCurrentCamera()->getViewport();
        osg::ref_ptr<osg::Image> image = new osg::Image;
        image->readPixels(static_cast<int>(vp->x()), static_cast<int>(vp->y()), static_cast<int>(vp->width()),
                          static_cast<int>(vp->height()), GL_RGB, GL_UNSIGNED_BYTE);
        osgDB::writeImageFile(*image, file);
        done = true;
    }
};

}  // namespace

int main(int argc, char** argv) {
    std::string model, technique = "sm", screenshot;
    int mapres = 2048, width = 1280, height = 720, frames = 30, warmup = 10;
    osg::Vec3 eye(0, 16, 30), target(0, 0, 0), sun(-0.4f, -1.0f, -0.3f);
    double fov = 45;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const char* next = i + 1 < argc ? argv[i + 1] : "";
        if (a == "--technique") technique = next, ++i;
        else if (a == "--mapres") mapres = std::atoi(next), ++i;
        else if (a == "--size") std::sscanf(next, "%dx%d", &width, &height), ++i;
        else if (a == "--eye") eye = vec3(next), ++i;
        else if (a == "--target") target = vec3(next), ++i;
        else if (a == "--sun") sun = vec3(next), ++i;
        else if (a == "--fov") fov = std::atof(next), ++i;
        else if (a == "--frames") frames = std::atoi(next), ++i;
        else if (a == "--warmup") warmup = std::atoi(next), ++i;
        else if (a == "--screenshot") screenshot = next, ++i;
        else model = a;
    }
    // Y-up like penumbra: no rotation to OSG's Z-up.
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options("noRotation");
    osg::ref_ptr<osg::Node> scene = osgDB::readRefNodeFile(model, options.get());
    if (!scene) {
        std::fprintf(stderr, "osgshadow_peer: cannot read %s\n", model.c_str());
        return 1;
    }
    osg::ref_ptr<osg::Material> material = new osg::Material;
    material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0.8f, 0.78f, 0.75f, 1));
    material->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0.08f, 0.08f, 0.09f, 1));
    scene->getOrCreateStateSet()->setAttributeAndModes(material.get());

    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    sun.normalize();
    light->getLight()->setPosition(osg::Vec4(-sun, 0.0f));  // directional: towards the light
    light->getLight()->setAmbient(osg::Vec4(0.08f, 0.08f, 0.09f, 1));
    light->getLight()->setDiffuse(osg::Vec4(1, 1, 1, 1));

    osg::ref_ptr<osg::Group> root;
    if (technique == "none") {
        root = new osg::Group;
    } else {
        osg::ref_ptr<osgShadow::ShadowedScene> shadowed = new osgShadow::ShadowedScene;
        osg::ref_ptr<osgShadow::ShadowSettings> settings = shadowed->getShadowSettings();
        settings->setTextureSize(osg::Vec2s(static_cast<short>(mapres), static_cast<short>(mapres)));
        if (technique == "sm") {
            osg::ref_ptr<osgShadow::ShadowMap> t = new osgShadow::ShadowMap;
            t->setTextureSize(osg::Vec2s(static_cast<short>(mapres), static_cast<short>(mapres)));
            shadowed->setShadowTechnique(t.get());
        } else if (technique == "ssm") {
            osg::ref_ptr<osgShadow::SoftShadowMap> t = new osgShadow::SoftShadowMap;
            t->setTextureSize(osg::Vec2s(static_cast<short>(mapres), static_cast<short>(mapres)));
            shadowed->setShadowTechnique(t.get());
        } else if (technique == "pssm") {
            osg::ref_ptr<osgShadow::ParallelSplitShadowMap> t = new osgShadow::ParallelSplitShadowMap(nullptr, 4);
            t->setTextureResolution(static_cast<unsigned>(mapres));
            shadowed->setShadowTechnique(t.get());
        } else if (technique == "lispsm") {
            osg::ref_ptr<osgShadow::LightSpacePerspectiveShadowMapDB> t = new osgShadow::LightSpacePerspectiveShadowMapDB;
            t->setTextureSize(osg::Vec2s(static_cast<short>(mapres), static_cast<short>(mapres)));
            shadowed->setShadowTechnique(t.get());
        } else {
            std::fprintf(stderr, "osgshadow_peer: unknown technique %s (none, sm, ssm, pssm, lispsm)\n", technique.c_str());
            return 1;
        }
        root = shadowed;
    }
    root->addChild(scene.get());
    root->addChild(light.get());

    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
    viewer.setUpViewInWindow(0, 0, width, height);
    viewer.setSceneData(root.get());
    viewer.getCamera()->setClearColor(osg::Vec4(0.45f, 0.6f, 0.8f, 1));
    viewer.getCamera()->setProjectionMatrixAsPerspective(fov, double(width) / height, 0.5, 120.0);
    viewer.getCamera()->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    viewer.getCamera()->setViewMatrixAsLookAt(eye, target, osg::Vec3(0, 1, 0));
    osg::ref_ptr<Capture> capture = new Capture;
    capture->file = screenshot;
    viewer.realize();
    for (int i = 0; i < warmup && !viewer.done(); ++i) viewer.frame();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames && !viewer.done(); ++i) viewer.frame();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / frames;
    viewer.getCamera()->setFinalDrawCallback(capture.get());
    viewer.frame();
    std::printf("osgshadow %s ms_per_frame %.3f frames %d mapres %d size %dx%d\n", technique.c_str(), ms, frames, mapres, width, height);
    return 0;
}
