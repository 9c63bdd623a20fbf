// A user library may add types but not take a name the project already has: the built-in
// would be kept and the user's model silently never run.
#include "core/Plugins.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "materials/Material.H"

#include <gtest/gtest.h>

using namespace gpic;

TEST(PluginRegistry, aLibraryRegisteringATakenNameIsAnErrorNamingBothLibraries)
{
    ASSERT_TRUE(Registry<Material<2>>::table().count("linearElastic"));
    const std::string builtIn = Registry<Material<2>>::table().at("linearElastic").library;
    EXPECT_NE(builtIn.find("libmaterials"), std::string::npos) << builtIn;
    try {
        Plugins::open(GPIC_DUPLICATE_PLUGIN, "system/controlDict", 7);
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("system/controlDict:7: library '", 0), 0u) << what;
        EXPECT_NE(what.find("material type 'linearElastic' of " + std::string(GPIC_DUPLICATE_PLUGIN)), std::string::npos)
            << what;
        EXPECT_NE(what.find("is already registered by " + builtIn), std::string::npos) << what;
    }
    // The project's type stays the one selected.
    EXPECT_EQ(Registry<Material<2>>::table().at("linearElastic").library, builtIn);
}

TEST(PluginRegistry, anEmptyLibraryNameIsAnError)
{
    // dlopen("") hands back the program itself: the library the user meant would silently
    // never be loaded.
    const Dictionary control = Dictionary::parse("\nlibs (\"\");\n", "system/controlDict");
    try {
        Plugins::open(control, "libs");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("system/controlDict:2: libs: an empty library name", 0), 0u) << e.what();
    }
}
