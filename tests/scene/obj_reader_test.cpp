// Reading OBJ meshes (scene/obj_reader): the forms people write (v/vt/vn corners, negative
// indices, polygons fanned from their first corner, o/g/s/usemtl/mtllib lines, CRLF and CR
// line ends), the diffuse colour of the .mtl, and every bad file refused with its line:
// indices out of range or zero, numbers that are not finite or out of range, faces of fewer
// than three corners, too many triangles, files that are missing, folders or FIFOs.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "scene/mtl_library.h"
#include "scene/obj_reader.h"
#include "scene/obj_text_checks.h"
#include "support/address_space_child.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::TempFolder;
using Triangle = std::array<std::uint32_t, 3>;
using Normals = std::array<std::int32_t, 3>;

// The message read_obj throws for `text`, or "" when it reads the file.
std::string error_for(const std::string& text) {
    TempFolder folder;
    try {
        read_obj(folder.write("mesh.obj", text));
    } catch (const ObjError& error) {
        return error.what();
    }
    return "";
}

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

// The error of reading a square whose face uses material `name` of m.mtl, written as `mtl`
// ("" when it reads).
std::string material_error(const std::string& mtl, const std::string& name) {
    TempFolder folder;
    folder.write("m.mtl", mtl);
    try {
        read_obj(folder.write("mesh.obj", "mtllib m.mtl\n" + kSquare + "usemtl " + name + "\nf 1 2 3\n"));
    } catch (const ObjError& error) {
        return error.what();
    }
    return "";
}

TEST(ObjReader, AQuadAndAPentagonFanFromTheirFirstCorner) {
    TempFolder folder;
    const ObjMesh mesh = read_obj(folder.write("mesh.obj", kSquare + "v 0.5 2 0\nf 1 2 3 4\nf 1 2 3 5 4\n"));
    EXPECT_EQ(mesh.faces, 2u);
    const std::vector<Triangle> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 4}, {0, 4, 3}};
    EXPECT_EQ(mesh.triangles, expected);
    ASSERT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.positions[4].x, 0.5);
    EXPECT_EQ(mesh.positions[4].y, 2.0);
}

TEST(ObjReader, CoordinatesAreReadInDouble) {
    TempFolder folder;
    const ObjMesh mesh = read_obj(folder.write("mesh.obj", "v 0.1 1e-300 123456789.123456789\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_EQ(mesh.positions[0].x, 0.1);
    EXPECT_EQ(mesh.positions[0].y, 1e-300);
    EXPECT_EQ(mesh.positions[0].z, 123456789.123456789);
}

TEST(ObjReader, EveryCornerFormAndNegativeIndices) {
    TempFolder folder;
    const std::string text = "o thing\ng part\ns 1\n" + kSquare +
                             "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nvn 0 0 -1\n"
                             "f 1/1/1 2/2/1 3/3/1\n"   // p/t/n
                             "f 1//2 3//2 4//2\n"      // p//n
                             "f 1/1 2/2 3/3\n"         // p/t
                             "f -4 -3 -1\n"            // relative: the 1st, 2nd and 4th position
                             "s off\nf 1/-3/-2 -3//-1 3/-1\n";
    const ObjMesh mesh = read_obj(folder.write("mesh.obj", text));
    const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 1, 3}, {0, 1, 2}};
    EXPECT_EQ(mesh.triangles, triangles);
    // The last face names a normal at two corners only: none is used (the geometric normal).
    EXPECT_EQ(mesh.triangle_normals, (std::vector<Normals>{{0, 0, 0}, {1, 1, 1}, {-1, -1, -1}, {-1, -1, -1},
                                                           {-1, -1, -1}}));
    EXPECT_EQ(mesh.normals.size(), 2u);
    EXPECT_EQ(mesh.normals[1].z, -1.0);
}

TEST(ObjReader, APositionDefinedAfterItsFaceIsFound) {
    TempFolder folder;
    const ObjMesh mesh = read_obj(folder.write("mesh.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"));
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}}));
}

TEST(ObjReader, CrlfAndCrLineEndsCountLinesAsTheyShow) {
    TempFolder folder;
    EXPECT_EQ(read_obj(folder.write("a.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n")).triangles.size(), 1u);
    EXPECT_EQ(read_obj(folder.write("b.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r")).triangles.size(), 1u);
    EXPECT_EQ(error_for("v 0 0 0\r\nv 1 0 0\r\n\r\nf 1 2 3\r\n"),
              "line 4: corner 3: position index 3 is out of range: the file has 2");
    EXPECT_EQ(error_for("v 0 0 0\rv 1 0 0\rf 1 2 3\r"), "line 3: corner 3: position index 3 is out of range: the file has 2");
}

// Editors on Windows start UTF-8 text with a byte order mark (EF BB BF): it is not part of
// the first line, which would otherwise be an unknown statement and shift every index.
TEST(ObjReader, AUtf8ByteOrderMarkIsSkipped) {
    TempFolder folder;
    const std::string bom = "\xEF\xBB\xBF";
    const ObjMesh mesh = read_obj(folder.write("bom.obj", bom + "v 5 6 7\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n"));
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[0], (Vec3{5, 6, 7}));
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}}));
    // The first line's number stays 1.
    EXPECT_EQ(error_for(bom + "v 0 nan 0\n"), "line 1: 'v': 'nan' is not a finite number");
    // In a .mtl too: the first material keeps its name, and its colour.
    folder.write("bom.mtl", bom + "newmtl red\nKd 1 0 0.25\n");
    const ObjMesh red = read_obj(folder.write("red.obj", "mtllib bom.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n"));
    EXPECT_EQ(red.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0.25}}));
    folder.write("bad.mtl", bom + "Kd 1 0\n");
    try {
        read_obj(folder.write("bad.obj", "mtllib bad.mtl\n" + kSquare + "f 1 2 3\n"));
        ADD_FAILURE() << "a Kd of two numbers after a byte order mark was read";
    } catch (const ObjError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "line 1: mtllib bad.mtl: line 1: 'Kd' needs 3 numbers (r g b), the line has 2");
    }
    // Only at the start: elsewhere it is text.
    EXPECT_EQ(error_for("v 0 0 0\n" + bom + "v 1 0 0\nv 0 1 0\nf 1 2 3\n"),
              "line 4: corner 3: position index 3 is out of range: the file has 2");
}

// A byte of a refused number or index that is no printable character (a NUL, an ESC) is shown
// escaped, as every message shows text: it was shown as a '?', which the file may hold itself
// or not at all (here the one '?' is the file's own).
TEST(ObjReader, AByteOfARefusedTokenThatIsNoCharacterIsShownEscaped) {
    EXPECT_EQ(error_for(std::string("v 1\0\x1b?5 0 0\n", 12)), "line 1: 'v': '1\\x00\\x1B?5' is not a finite number");
    EXPECT_EQ(error_for(kSquare + std::string("f 1 2 3\0\n", 9)), "line 5: corner 3: '3\\x00' is not a position index");
}

// Forms that OBJ writers use: a '+' sign on a number or an index, and a comment after a
// statement. tinyobjloader must read them as the checks do.
TEST(ObjReader, PlusSignsAndTrailingCommentsAreRead) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl red\nKd +1 0 +0.25 # red\n");
    const ObjMesh mesh = read_obj(folder.write(
        "mesh.obj", "mtllib m.mtl\nv +1 0 0 # first\nv 0 +2.5 0\nv 0 0 +1e+1\nv 1 1 1\t#tab\n"
                    "vn 0 0 +1 # up\nvt 0.5 +0.5 # uv\nusemtl red\nf 1//1 2//1 3//1 # tri\nf +1 +2 +4 #\n"));
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[0], (Vec3{1, 0, 0}));
    EXPECT_EQ(mesh.positions[1], (Vec3{0, 2.5, 0}));
    EXPECT_EQ(mesh.positions[2], (Vec3{0, 0, 10}));
    EXPECT_EQ(mesh.positions[3], (Vec3{1, 1, 1}));
    ASSERT_EQ(mesh.normals.size(), 1u);
    EXPECT_EQ(mesh.normals[0], (Vec3{0, 0, 1}));
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 1, 3}}));
    EXPECT_EQ(mesh.triangle_normals, (std::vector<Normals>{{0, 0, 0}, {-1, -1, -1}}));
    EXPECT_EQ(mesh.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0.25}}));
    // A comment is not a corner, and a sign is one sign.
    EXPECT_EQ(error_for(kSquare + "f 1 2 # 3\n"), "line 5: a face needs 3 corners or more, this one has 2");
    EXPECT_EQ(error_for("v +-1 0 0\n"), "line 1: 'v': '+-1' is not a finite number");
    EXPECT_EQ(error_for("v ++1 0 0\n"), "line 1: 'v': '++1' is not a finite number");
    EXPECT_EQ(error_for("v + 0 0\n"), "line 1: 'v': '+' is not a finite number");
    EXPECT_EQ(error_for(kSquare + "f 1 2 +-3\n"), "line 5: corner 3: '+-3' is not a position index");
    EXPECT_EQ(error_for(kSquare + "f 1 2 +9\n"), "line 5: corner 3: position index 9 is out of range: the file has 4");
}

// A '#' starts a comment only at the start of a word: old MSVC runtimes write infinity and NaN
// as "1.#INF", "-1.#IND00" and "1.#QNAN", which cut at the '#' were read as 1 and -1 and drawn
// so, without a word. Such a number, and any word with a '#' inside, is refused at its line.
TEST(ObjReader, AHashInsideAWordIsPartOfIt) {
    EXPECT_EQ(error_for("v -1 -1 0\nv 1 -1 0\nv 1 1 1.#INF\nf 1 2 3\n"),
              "line 3: 'v': '1.#INF' is not a finite number");
    EXPECT_EQ(error_for("v 1 1 -1.#IND00\n"), "line 1: 'v': '-1.#IND00' is not a finite number");
    EXPECT_EQ(error_for("v 1 1 1#junk\n"), "line 1: 'v': '1#junk' is not a finite number");
    EXPECT_EQ(error_for("v 0 0 0 1.#QNAN0\n"), "line 1: 'v': '1.#QNAN0' is not a finite number");  // a weight
    EXPECT_EQ(error_for("v 0 0 0\nvn 0 0 -1.#QNAN\n"), "line 2: 'vn': '-1.#QNAN' is not a finite number");
    // Cut at the first '#', this line had one number ("needs 3 numbers, the line has 1").
    EXPECT_EQ(error_for("v 0 0 0\nvn -1.#IND -1.#IND -1.#IND\n"), "line 2: 'vn': '-1.#IND' is not a finite number");
    EXPECT_EQ(error_for("vt 0.5 1.#INF\n"), "line 1: 'vt': '1.#INF' is not a finite number");
    EXPECT_EQ(error_for(kSquare + "f 1 2 3#tri\n"), "line 5: corner 3: '3#tri' is not a position index");
    EXPECT_EQ(error_for(kSquare + "f 1 2 4//1#n\n"), "line 5: corner 3: '1#n' is not a normal index");
    EXPECT_EQ(error_for("v#1 0 0 0\n"), "");  // no statement: an unknown word, which a warning names
    const auto mtl_error = [](const std::string& colour) {
        return material_error("newmtl blue\n" + colour + "\n", "blue");
    };
    EXPECT_EQ(mtl_error("Kd 0 0 1.#INF00"), "line 1: mtllib m.mtl: line 2: 'Kd': '1.#INF00' is not a finite number");
    EXPECT_EQ(mtl_error("Kd 0.2 0.3 -1.#IND00"),
              "line 1: mtllib m.mtl: line 2: 'Kd': '-1.#IND00' is not a finite number");
    EXPECT_EQ(mtl_error("Kd 0 0 1 # blue"), "");
}

TEST(ObjReader, TheMaterialsDiffuseColourIsTheMeshColour) {
    TempFolder folder;
    folder.write("colours.mtl", "newmtl red\nKd 1 0 0.25\nnewmtl plain\nKs 1 1 1\n");
    const std::string faces = "mtllib colours.mtl\n" + kSquare;
    EXPECT_EQ(read_obj(folder.write("red.obj", faces + "usemtl red\nf 1 2 3\nusemtl plain\nf 1 3 4\n")).diffuse,
              (std::optional<Vec3>{Vec3{1, 0, 0.25}}));
    // A material without Kd leaves the colour to the scene (tinyobjloader's 0 is not a colour).
    EXPECT_FALSE(read_obj(folder.write("plain.obj", faces + "usemtl plain\nf 1 2 3\n")).diffuse.has_value());
    EXPECT_FALSE(read_obj(folder.write("none.obj", kSquare + "f 1 2 3\n")).diffuse.has_value());
}

// clrender knows which materials give a Kd as tinyobjloader names and picks them: a name
// defined twice is its first definition, and a name ends before trailing blanks (a tab too).
TEST(ObjReader, MaterialNamesAreReadAsTinyobjloaderReadsThem) {
    TempFolder folder;
    const auto diffuse_of = [&](const std::string& material) {
        folder.write("m.mtl", material);
        return read_obj(folder.write("mesh.obj", "mtllib m.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n")).diffuse;
    };
    // The first definition gives no Kd: the scene's colour, not black.
    EXPECT_FALSE(diffuse_of("newmtl red\nnewmtl red\nKd 0 1 0\n").has_value());
    EXPECT_EQ(diffuse_of("newmtl red\nKd 0 0 1\nnewmtl red\nKd 0 1 0\n"), (std::optional<Vec3>{Vec3{0, 0, 1}}));
    EXPECT_EQ(diffuse_of("newmtl red\t\nKd 1 0 0\n"), (std::optional<Vec3>{Vec3{1, 0, 0}}));
    EXPECT_EQ(diffuse_of("newmtl red \t \r\nKd 1 0 0.5\r\n"), (std::optional<Vec3>{Vec3{1, 0, 0.5}}));
    EXPECT_EQ(diffuse_of("newmtl\tred\nKd 0.5 0 0\n"), (std::optional<Vec3>{Vec3{0.5, 0, 0}}));
    // A Kd before any name, and a `newmtl` without one, belong to no material that usemtl finds.
    EXPECT_EQ(diffuse_of("Kd 0 1 0\nnewmtl red\nKd 0.25 0 0\nnewmtl\nKd 0 0 1\n"),
              (std::optional<Vec3>{Vec3{0, 0, 1}}))
        << "tinyobjloader reads a Kd after a bare 'newmtl' as the current material's";
    // Several .mtl files: materials are counted across them.
    folder.write("a.mtl", "newmtl blue\nnewmtl green\nKd 0 1 0\n");
    folder.write("b.mtl", "newmtl red\nKd 1 0 0\n");
    EXPECT_EQ(read_obj(folder.write("two.obj", "mtllib a.mtl\nmtllib b.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n")).diffuse,
              (std::optional<Vec3>{Vec3{1, 0, 0}}));
    EXPECT_FALSE(read_obj(folder.write("two.obj", "mtllib a.mtl b.mtl\n" + kSquare + "usemtl blue\nf 1 2 3\n"))
                     .diffuse.has_value());
}

// A `newmtl my mat` defines "my mat" (LoadMtl keeps the rest of the line), which a `usemtl my mat`
// names whole; a name that no .mtl defines whole is its first word, as tinyobjloader reads a
// `usemtl`. Such a material was never found: the mesh drawn grey, and a warning that no .mtl
// defined "my".
TEST(ObjReader, AMaterialNameWithBlanksIsFoundWhole) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl my mat\nKd 1 0 0\nnewmtl wood\nKd 0 1 0\n");
    const auto read = [&](const std::string& uses) {
        return read_obj(folder.write("mesh.obj", "mtllib m.mtl\n" + kSquare + uses));
    };
    const ObjMesh whole = read("usemtl my mat\nf 1 2 3\nusemtl  my mat  # red\nf 1 3 4\n");
    EXPECT_EQ(whole.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0}}));
    EXPECT_TRUE(whole.warnings.empty()) << whole.warnings[0];
    const ObjMesh first_word = read("usemtl wood oak\nf 1 2 3\n");
    EXPECT_EQ(first_word.diffuse, (std::optional<Vec3>{Vec3{0, 1, 0}}));
    EXPECT_TRUE(first_word.warnings.empty()) << first_word.warnings[0];
    const ObjMesh neither = read("usemtl my other mat\nf 1 2 3\n");
    EXPECT_FALSE(neither.diffuse.has_value());
    ASSERT_EQ(neither.warnings.size(), 1u);
    EXPECT_EQ(neither.warnings[0].rfind("line 6: usemtl my other mat: no .mtl file of the OBJ defines this material", 0),
              0u)
        << neither.warnings[0];
    const ObjMesh other_colour = read("usemtl wood\nf 1 2 3\nusemtl my mat\nf 1 3 4\n");
    EXPECT_EQ(other_colour.diffuse, (std::optional<Vec3>{Vec3{0, 1, 0}}));
    ASSERT_EQ(other_colour.warnings.size(), 1u);
    EXPECT_EQ(other_colour.warnings[0].rfind("line 8: usemtl my mat: a mesh takes one colour", 0), 0u)
        << other_colour.warnings[0];
}

// A material defined again keeps its first definition: the later one's colour is unused, which
// a warning says, with the .mtl's line (across .mtl files too).
TEST(ObjReader, AMaterialDefinedAgainIsAWarning) {
    TempFolder folder;
    folder.write("a.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\n\nnewmtl red\t\nKd 0 1 0\n");
    folder.write("b.mtl", "newmtl blue\nnewmtl green\n");
    const ObjMesh one = read_obj(folder.write("one.obj", "mtllib a.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n"));
    EXPECT_EQ(one.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0}}));
    EXPECT_EQ(one.warnings, (std::vector<std::string>{
                                "mtllib a.mtl: line 5: newmtl red: the material is defined again; the first definition is used"}));
    const ObjMesh two = read_obj(folder.write("two.obj", "mtllib a.mtl\nmtllib b.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n"));
    EXPECT_EQ(two.warnings, (std::vector<std::string>{
                                "mtllib a.mtl: line 5: newmtl red: the material is defined again; the first definition is "
                                "used (and 1 more materials defined again)"}));
    folder.write("c.mtl", "newmtl red\nnewmtl reds\nnewmtl  red\n");  // "red" again (mtl_material_name)
    EXPECT_EQ(read_obj(folder.write("c.obj", "mtllib c.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n")).warnings,
              (std::vector<std::string>{
                  "mtllib c.mtl: line 3: newmtl red: the material is defined again; the first definition is used"}));
}

// `newmtl  red` (two blanks) defines "red", which `usemtl red` names: tinyobjloader keeps the
// blank (" red"), and the mesh was drawn grey with a warning that no .mtl defined "red".
TEST(ObjReader, AMaterialNameIsReadWithoutTheBlanksBeforeIt) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl  red\nKd 1 0 0\nmap_Kd red.png\nnewmtl \t blue \nKd 0 0 1\n");
    const auto read = [&](const std::string& material) {
        return read_obj(folder.write("mesh.obj", "mtllib m.mtl\n" + kSquare + "usemtl " + material + "\nf 1 2 3\n"));
    };
    const ObjMesh red = read("red");
    EXPECT_EQ(red.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0}}));
    EXPECT_EQ(red.warnings, (std::vector<std::string>{
                                "mtllib m.mtl: line 3: map_Kd red.png: a mesh takes one colour, the scene's ambient or "
                                "else its first face's material's Kd; this texture is not drawn"}));
    const ObjMesh blue = read("blue");
    EXPECT_EQ(blue.diffuse, (std::optional<Vec3>{Vec3{0, 0, 1}}));
    EXPECT_TRUE(blue.warnings.empty()) << blue.warnings[0];
}

// A Kd before the first newmtl is the colour of no material, which tinyobjloader drops: the mesh
// came out grey with nothing said. A warning names its .mtl line.
TEST(ObjReader, AColourBeforeTheFirstMaterialIsAWarning) {
    TempFolder folder;
    const std::string warning = ": a Kd before the first newmtl is the colour of no material: the line is ignored";
    folder.write("early.mtl", "# colours\nKd 1 0 0\nnewmtl red\nKd 0 1 0\nKd 0 0 1\n");
    const ObjMesh early = read_obj(folder.write("early.obj", "mtllib early.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n"));
    EXPECT_EQ(early.warnings, (std::vector<std::string>{"mtllib early.mtl: line 2" + warning}));
    // A file without a newmtl: tinyobjloader keeps the colour as a nameless material's, which
    // faces without a usemtl take.
    folder.write("none.mtl", "Kd 1 0 0\n");
    const ObjMesh none = read_obj(folder.write("none.obj", "mtllib none.mtl\n" + kSquare + "f 1 2 3\n"));
    EXPECT_EQ(none.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0}}));
    EXPECT_TRUE(none.warnings.empty()) << none.warnings[0];
    folder.write("late.mtl", "newmtl red\nKd 0 1 0\n");
    EXPECT_TRUE(read_obj(folder.write("late.obj", "mtllib late.mtl\n" + kSquare + "f 1 2 3\n")).warnings.empty());
}

// A scene's OBJ files share one MtlLibrary, which lists each .mtl's materials once: each OBJ
// still combines its files in its own order, a name's first definition kept and a later one a
// warning naming the file that defines it again.
TEST(ObjReader, ObjFilesSharingALibraryCombineItsFilesInTheirOwnOrder) {
    TempFolder folder;
    folder.write("a.mtl", "newmtl red\nKd 1 0 0\nnewmtl only_a\nKd 0 0 1\n");
    folder.write("b.mtl", "newmtl red\nKd 0 1 0\n");
    MtlLibrary library;
    const std::string a_then_b = folder.write("ab.obj", "mtllib a.mtl b.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n");
    const std::string b_then_a = folder.write("ba.obj", "mtllib b.mtl a.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n");
    const std::string only_b = folder.write("b.obj", "mtllib b.mtl\n" + kSquare + "usemtl only_a\nf 1 2 3\n");
    for (int round = 0; round < 2; ++round) {  // the files' first reads, then the library's kept ones
        const ObjMesh ab = parse_obj(testing::read_bytes(a_then_b), a_then_b, UINT64_MAX, &library);
        EXPECT_EQ(ab.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0}}));
        EXPECT_EQ(ab.warnings, (std::vector<std::string>{"mtllib b.mtl: line 1: newmtl red: the material is defined "
                                                         "again; the first definition is used"}));
        const ObjMesh ba = parse_obj(testing::read_bytes(b_then_a), b_then_a, UINT64_MAX, &library);
        EXPECT_EQ(ba.diffuse, (std::optional<Vec3>{Vec3{0, 1, 0}}));
        EXPECT_EQ(ba.warnings, (std::vector<std::string>{"mtllib a.mtl: line 1: newmtl red: the material is defined "
                                                         "again; the first definition is used"}));
        const ObjMesh b = parse_obj(testing::read_bytes(only_b), only_b, UINT64_MAX, &library);
        EXPECT_EQ(b.diffuse, std::nullopt);
        ASSERT_EQ(b.warnings.size(), 1u);
        EXPECT_NE(b.warnings[0].find("usemtl only_a: no .mtl file of the OBJ defines this material"), std::string::npos)
            << b.warnings[0];
    }
}

// A .mtl is read and parsed once for all the OBJ files of a scene, however large its parsed
// form: one of 10,000 long material names, each with a texture (about 67 MiB held), was past the
// 64 MiB the library kept, and each OBJ naming it read and parsed it again (30 small OBJ files
// took 11 s, 1,000 would take minutes). Counted in parses, not seconds.
TEST(ObjReader, ALargeLibraryIsParsedOnceForAllTheObjFilesNamingIt) {
    TempFolder folder;
    const std::string long_name(1640, 'q');
    std::string text;
    for (int m = 0; m < 10000; ++m) text += "newmtl m" + std::to_string(100000 + m) + long_name + "\nmap_Kd t\n";
    ASSERT_LE(text.size(), kMaxMtlFileBytes);
    folder.write("large.mtl", text);
    MtlLibrary library;
    for (int i = 0; i < 3; ++i) {
        const std::string obj =
            folder.write("part" + std::to_string(i) + ".obj", "mtllib large.mtl\n" + kSquare + "f 1 2 3\n");
        EXPECT_EQ(parse_obj(testing::read_bytes(obj), obj, UINT64_MAX, &library).faces, 1u);
    }
    EXPECT_EQ(library.files_parsed(), 1u);
}

// What the library keeps is bounded: a .mtl that would take the files it holds past its bound
// is refused as out of memory, naming the file (exit 6 at the mesh's filename), and the files
// kept stay kept.
TEST(ObjReader, LibrariesPastTheirBoundEndTheRunNamingTheFile) {
    TempFolder folder;
    const std::string small = folder.write("small.mtl", "newmtl red\nKd 1 0 0\n");
    std::string text;
    for (int m = 0; m < 5000; ++m) text += "newmtl a_material_with_a_rather_long_name_" + std::to_string(m) + "\n";
    const std::string large = folder.write("large.mtl", text);
    MtlLibrary library(std::uint64_t(1) << 20);
    library.read(small);
    try {
        library.read(large);
        ADD_FAILURE() << "read past the bound";
    } catch (const MeshMemoryError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "the .mtl '" + large + "' takes about 2 MiB to hold once read (its material names and texture "
                  "statements), which brings the .mtl files the scene holds past the 1 MiB they may take "
                  "(docs/robustness.md, Memory)");
    }
    library.read(small);
    EXPECT_EQ(library.files_parsed(), 2u);
}

// A usemtl that names no material is a warning with its line (tinyobjloader's own says
// neither file nor line), counting the others; a name it finds is none.
TEST(ObjReader, AMaterialThatNoMtlDefinesIsAWarning) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl rde\nKd 1 0 0\nnewmtl red  \n");  // "red": trailing blanks are no part of it
    const ObjMesh mesh = read_obj(folder.write(
        "mesh.obj", "mtllib m.mtl\n" + kSquare + "usemtl red\nf 1 2 3\nusemtl blue\nf 1 3 4\nusemtl blue # again\n"
                    "usemtl rde\nf 2 3 4\n"));
    EXPECT_EQ(mesh.triangles.size(), 3u);
    EXPECT_FALSE(mesh.diffuse.has_value());
    EXPECT_EQ(mesh.warnings, (std::vector<std::string>{
                                 "line 8: usemtl blue: no .mtl file of the OBJ defines this material (nor those of 1 "
                                 "more usemtl lines); its faces take the scene's ambient, else 0.8 grey",
                                 "line 11: usemtl rde: a mesh takes one colour, the scene's ambient or else its first "
                                 "face's material's Kd; this material's Kd is not used"}));
    const ObjMesh none = read_obj(folder.write("none.obj", kSquare + "usemtl red\nf 1 2 3\n"));
    ASSERT_EQ(none.warnings.size(), 1u);
    EXPECT_EQ(none.warnings[0].rfind("line 5: usemtl red: no .mtl file", 0), 0u) << none.warnings[0];
    EXPECT_TRUE(read_obj(folder.write("fine.obj", "mtllib m.mtl\n" + kSquare + "usemtl rde\nf 1 2 3\n")).warnings.empty());
}

// tinyobjloader keeps about 3 KB a material: an OBJ's .mtl files define at most
// kMaxObjMaterials together, counted before the library reads them.
TEST(ObjReader, TheMaterialsOfAnObjAreLimited) {
    TempFolder folder;
    std::string materials;
    for (std::uint64_t i = 0; i < kMaxObjMaterials; ++i) materials += "newmtl m" + std::to_string(i) + "\n";
    folder.write("full.mtl", materials);
    folder.write("more.mtl", "newmtl red\nKd 1 0 0\n");
    const std::string faces = kSquare + "usemtl m9999\nf 1 2 3\n";
    EXPECT_TRUE(read_obj(folder.write("full.obj", "mtllib full.mtl\n" + faces)).warnings.empty());
    try {
        read_obj(folder.write("over.obj", "mtllib full.mtl\nmtllib more.mtl\n" + faces));
        ADD_FAILURE() << "10001 materials were read";
    } catch (const ObjError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "line 2: mtllib more.mtl: it brings the OBJ's materials to 10001, more than the limit of 10000");
    }
}

// One .mtl named several ways is read once: its materials are not counted (nor kept) twice.
TEST(ObjReader, AMaterialFileNamedSeveralWaysIsReadOnce) {
    TempFolder folder;
    std::string materials = "newmtl red\nKd 1 0 0\n";
    for (int i = 0; i < 6000; ++i) materials += "newmtl m" + std::to_string(i) + "\n";
    folder.write("a.mtl", materials);
    ::mkdir(folder.file("sub").c_str(), 0755);
    const ObjMesh mesh = read_obj(folder.write(
        "mesh.obj", "mtllib a.mtl\nmtllib ./a.mtl\nmtllib .//a.mtl\nmtllib sub/../a.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n"));
    EXPECT_EQ(mesh.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0}}));
    EXPECT_TRUE(mesh.warnings.empty()) << "its materials were read again: " << mesh.warnings.front();
    // Listed under each name, with the one digest, for the mesh cache's check of each name.
    ASSERT_EQ(mesh.material_files.size(), 4u);
    ASSERT_EQ(mesh.material_digests.size(), 4u);
    for (const Sha256Digest& digest : mesh.material_digests) EXPECT_EQ(digest, mesh.material_digests[0]);
}

// Every name of an `mtllib` statement is a .mtl file the OBJ reads, however they are spelt
// (tinyobjloader reads only the first it can), and a usemtl finds a material of a file
// named on a later line; a missing file is an error wherever it is named.
TEST(ObjReader, EveryMaterialFileIsReadBeforeTheFaces) {
    TempFolder folder;
    folder.write("a.mtl", "newmtl red\nKd 1 0 0\n");
    folder.write("b.mtl", "newmtl blue\nKd 0 0 1\n");
    const std::optional<Vec3> blue{Vec3{0, 0, 1}};
    for (const std::string libraries : {"mtllib a.mtl b.mtl\n", "mtllib ./a.mtl b.mtl\n", "mtllib  a.mtl   b.mtl\n"}) {
        const ObjMesh mesh = read_obj(folder.write("two.obj", libraries + kSquare + "usemtl blue\nf 1 2 3\n"));
        EXPECT_EQ(mesh.diffuse, blue) << libraries;
        EXPECT_TRUE(mesh.warnings.empty()) << libraries << mesh.warnings.front();
        EXPECT_EQ(mesh.material_files.size(), 2u) << libraries;
    }
    const ObjMesh later = read_obj(folder.write("later.obj", kSquare + "usemtl blue\nf 1 2 3\nmtllib a.mtl b.mtl\n"));
    EXPECT_EQ(later.diffuse, blue);
    EXPECT_TRUE(later.warnings.empty()) << later.warnings.front();
    folder.write("a b.mtl", "newmtl green\nKd 0 1 0\n");
    EXPECT_EQ(read_obj(folder.write("space.obj", "mtllib a\\ b.mtl\n" + kSquare + "usemtl green\nf 1 2 3\n")).diffuse,
              (std::optional<Vec3>{Vec3{0, 1, 0}}));
    for (const std::string libraries : {"mtllib a.mtl gone.mtl\n", "mtllib gone.mtl a.mtl\n"}) {
        try {
            read_obj(folder.write("gone.obj", libraries + kSquare + "f 1 2 3\n"));
            ADD_FAILURE() << libraries << "read without its missing .mtl";
        } catch (const ObjError& error) {
            EXPECT_EQ(std::string(error.what()).rfind("line 1: mtllib gone.mtl: ", 0), 0u) << libraries << error.what();
        }
    }
}

// "mtllib My Model.mtl", as Blender writes the .mtl of a model saved as "My Model.obj" (and as
// three.js and Assimp read it): the whole rest of the line names that file. Cut at the space, it
// named "My", no file, and the model was refused ("line 1: mtllib My: no such file"). A line
// whose whole rest names no file is still cut into names, and the file is listed among the
// model's own for a model that fails at a later line too.
TEST(ObjReader, AnMtllibLineThatNamesOneFileWithASpaceReadsIt) {
    TempFolder folder;
    folder.write("My Model.mtl", "newmtl red\nKd 1 0 0\n");
    for (const std::string line : {"mtllib My Model.mtl\n", "mtllib   My Model.mtl \t\n", "mtllib My Model.mtl\r\n"}) {
        const ObjMesh mesh = read_obj(folder.write("My Model.obj", line + kSquare + "usemtl red\nf 1 2 3\n"));
        EXPECT_EQ(mesh.diffuse, (std::optional<Vec3>{Vec3{1, 0, 0}})) << line;
        EXPECT_TRUE(mesh.warnings.empty()) << line << mesh.warnings.front();
        ASSERT_EQ(mesh.material_files.size(), 1u) << line;
        EXPECT_EQ(mesh.material_files[0], folder.file("My Model.mtl")) << line;
    }
    try {
        read_obj(folder.write("broken.obj", "mtllib My Model.mtl\n" + kSquare + "f 1 2 9\n"));
        ADD_FAILURE() << "a face of a missing position was read";
    } catch (const ObjError& error) {
        EXPECT_EQ(error.material_files, std::vector<std::string>{folder.file("My Model.mtl")});
    }
    try {
        read_obj(folder.write("other.obj", "mtllib Other Model.mtl\n" + kSquare + "f 1 2 3\n"));
        ADD_FAILURE() << "read without its .mtl";
    } catch (const ObjError& error) {
        EXPECT_EQ(std::string(error.what()), "line 1: mtllib Other: no such file");
    }
}

// A line of millions of words is refused at the words it may have, without a list of them
// all (about 17 times the line's size): checked in a child whose address space may grow by
// 400 MiB, with a 64 MiB line whose list of words alone would take 512 MiB.
TEST(ObjReader, ALineOfMillionsOfWordsIsRefusedWithoutHoldingThem) {
#ifdef __SANITIZE_ADDRESS__
    GTEST_SKIP() << "AddressSanitizer's allocator reserves address space of its own";
#endif
    for (const std::string keyword : {"f", "v"}) {
        std::string text = kSquare + keyword;
        constexpr std::size_t kWords = std::size_t(32) << 20;
        text.reserve(text.size() + 2 * kWords + 1);
        for (std::size_t i = 0; i < kWords; ++i) text += " 1";
        text += "\n";
        const std::string expected = keyword == "f" ? "line 5: a face has at most 255 corners (tinyobjloader's limit), this "
                                                      "one has 33554432: split it into smaller faces"
                                                    : "line 5: 'v' has at most 255 numbers, this line has 33554432";
        const bool refused = testing::passes_in_bounded_child({std::uint64_t(400) << 20}, [&] {
            try {
                parse_obj(text, "mesh.obj");
            } catch (const ObjError& error) {
                return error.what() == expected;
            }
            return false;
        });
        EXPECT_TRUE(refused) << keyword << ": not refused with \"" << expected
                                                                  << "\" within the bound";
    }
    std::string numbers;
    for (int i = 0; i < 255; ++i) numbers += " 1";
    EXPECT_EQ(error_for(kSquare + "v" + numbers + "\nf 1 2 3\n"), "");
    EXPECT_EQ(error_for(kSquare + "v" + numbers + " 1\nf 1 2 3\n"), "line 5: 'v' has at most 255 numbers, this line has 256");
}

// More .mtl files than kMaxMtlFiles are refused at the first one past the limit.
TEST(ObjReader, TheMaterialFilesOfAnObjAreLimited) {
    TempFolder folder;
    std::string libraries;
    for (std::uint64_t i = 0; i <= kMaxMtlFiles; ++i) {
        const std::string name = "m" + std::to_string(i) + ".mtl";
        folder.write(name, "newmtl m" + std::to_string(i) + "\n");
        libraries += "mtllib " + name + "\n";
        if (i + 1 == kMaxMtlFiles) {
            EXPECT_EQ(read_obj(folder.write("full.obj", libraries + kSquare + "f 1 2 3\n")).material_files.size(), kMaxMtlFiles);
        }
    }
    try {
        read_obj(folder.write("over.obj", libraries + kSquare + "f 1 2 3\n"));
        ADD_FAILURE() << "1025 .mtl files were read";
    } catch (const ObjError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "line 1025: mtllib m1024.mtl: the OBJ reads more than 1024 .mtl files, the limit");
    }
}

TEST(ObjReader, AMissingMaterialFileIsAnError) {
    const std::string message = error_for("mtllib gone.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n");
    EXPECT_EQ(message.rfind("line 1: mtllib gone.mtl: ", 0), 0u) << message;
    EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

// A .mtl that cannot be read is named with the OBJ's line that names it, as every other problem
// of the OBJ is: "mtllib mdir: it is a folder" said not where.
TEST(ObjReader, AMaterialFileProblemNamesTheObjLine) {
    TempFolder folder;
    folder.write("ok.mtl", "newmtl red\nKd 1 0 0\n");
    ::mkdir(folder.file("mdir").c_str(), 0755);
    ASSERT_EQ(::mkfifo(folder.file("fifo.mtl").c_str(), 0600), 0);
    for (const std::string name : {"mdir", "fifo.mtl", "gone.mtl"}) {
        const std::string text = "# materials\n\nmtllib ok.mtl " + name + "\nmtllib ok.mtl\n" + kSquare + "f 1 2 3\n";
        try {
            read_obj(folder.write("mesh.obj", text));
            ADD_FAILURE() << name << " was read";
        } catch (const ObjError& error) {
            EXPECT_EQ(std::string(error.what()).rfind("line 3: mtllib " + name + ": ", 0), 0u) << error.what();
        }
    }
}

// The name comes from the file: its control characters are escaped, not printed.
TEST(ObjReader, AMaterialFileNameIsPrintedEscaped) {
    const std::string message = error_for("mtllib bad\x1b[2Jname.mtl\n" + kSquare + "f 1 2 3\n");
    EXPECT_EQ(message.rfind("line 1: mtllib bad\\x1B[2Jname.mtl: ", 0), 0u) << message;
}

TEST(ObjReader, BadIndicesNameTheirLineAndCorner) {
    EXPECT_EQ(error_for(kSquare + "f 1 2 3\nf 1 2 9\n"), "line 6: corner 3: position index 9 is out of range: the file has 4");
    EXPECT_EQ(error_for(kSquare + "f 0 1 2\n"), "line 5: corner 1: position index 0: indices count from 1 (or back from -1)");
    EXPECT_EQ(error_for("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n"),
              "line 3: corner 3: position index -3 is out of range: 2 precede this line");
    EXPECT_EQ(error_for(kSquare + "vn 0 0 1\nf 1//1 2//2 3//1\n"),
              "line 6: corner 2: normal index 2 is out of range: the file has 1");
    EXPECT_EQ(error_for(kSquare + "f 1/1 2/1 3/1\n"), "line 5: corner 1: texture coordinate index 1 is out of range: the file has 0");
    EXPECT_EQ(error_for(kSquare + "f 1 2 x\n"), "line 5: corner 3: 'x' is not a position index");
    EXPECT_EQ(error_for(kSquare + "f 1/1/1/1 2 3\n"), "line 5: corner 1: '1/1/1/1' is not a corner (p, p/t, p//n or p/t/n)");
    EXPECT_EQ(error_for(kSquare + "f 99999999999999999999 2 3\n"), "line 5: corner 1: '99999999999999999999' is not a position index");
}

// "1/" names no texture coordinate: refused at its line, as the other corner forms are.
TEST(ObjReader, ACornerEndingInASlashIsRefusedAtItsLine) {
    EXPECT_EQ(error_for(kSquare + "f 1/ 2/ 3/\n"), "line 5: corner 1: '1/' is not a corner (p, p/t, p//n or p/t/n)");
    EXPECT_EQ(error_for(kSquare + "vt 0 0\nf 1/1 2/1 3/\n"), "line 6: corner 3: '3/' is not a corner (p, p/t, p//n or p/t/n)");
}

// A file saved as UTF-16 or compressed with gzip is named as such, not as a file of unknown
// statements and no faces; the same for its .mtl.
TEST(ObjReader, Utf16AndGzipFilesAreNamedAsSuch) {
    const auto utf16 = [](const std::string& ascii, bool mark) {
        std::string wide = mark ? "\xFF\xFE" : "";
        for (char c : ascii) wide += std::string{c, '\0'};
        return wide;
    };
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    EXPECT_EQ(error_for(utf16(triangle, true)), "it is UTF-16 (little-endian) text; save it as UTF-8 (clrender reads only UTF-8)");
    EXPECT_EQ(error_for(utf16(triangle, false)), "it is UTF-16 (little-endian) text; save it as UTF-8 (clrender reads only UTF-8)");
    EXPECT_EQ(error_for(std::string("\x1F\x8B\x08\0\0\0\0\0", 8) + "compressed"), "it is gzip-compressed; decompress it first");
    TempFolder folder;
    folder.write("wide.mtl", utf16("newmtl red\nKd 1 0 0\n", true));
    try {
        read_obj(folder.write("mesh.obj", "mtllib wide.mtl\nusemtl red\n" + triangle));
        ADD_FAILURE() << "a UTF-16 .mtl was read";
    } catch (const ObjError& error) {
        EXPECT_EQ(std::string(error.what()), "line 1: mtllib wide.mtl: it is UTF-16 (little-endian) text; save it as "
                                             "UTF-8 (clrender reads only UTF-8)");
    }
}

// An OBJ kept compressed with another tool than gzip, or in an archive, and named .obj: each
// named as such (the first bytes as the tools write them). Read as text they were "no faces",
// or the error of a line that a block stored uncompressed held (a zstd file of a triangle:
// "line 2: 'v': 'f' is not a finite number").
TEST(ObjReader, CompressedAndArchivedFilesAreNamedAsSuch) {
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {std::string("\x28\xB5\x2F\xFD\x24\x23\xE5\0\0\x90", 10) + triangle,
         "it is zstd-compressed; decompress it first"},
        {std::string("\xFD" "7zXZ\0\0\x04\xE6\xD6\xB4\x46", 12), "it is xz-compressed; decompress it first"},
        {"BZh91AY&SY\xF6\xA5", "it is bzip2-compressed; decompress it first"},
        {std::string("\x04\x22\x4D\x18\x64\x40\xA7", 7) + triangle, "it is LZ4-compressed; decompress it first"},
        {std::string("7z\xBC\xAF\x27\x1C\0\x04", 8), "it is a 7-Zip archive; extract the file first"},
        {std::string("PK\x03\x04\x14\0\0\0\x08\0", 10) + "mesh.obj" + triangle,
         "it is a ZIP archive; extract the file first"},
    };
    for (const auto& [text, expected] : cases) EXPECT_EQ(error_for(text), expected);
    // Text that merely starts as bzip2's mark does is read as text.
    EXPECT_EQ(error_for("BZh 1 2 3\n" + triangle).find("compressed"), std::string::npos);
    TempFolder folder;
    folder.write("packed.mtl", std::string("\x28\xB5\x2F\xFD\x24\x23\xE5\0\0\x90", 10) + "newmtl red\nKd 1 0 0\n");
    try {
        read_obj(folder.write("mesh.obj", "mtllib packed.mtl\nusemtl red\n" + triangle));
        ADD_FAILURE() << "a zstd .mtl was read";
    } catch (const ObjError& error) {
        EXPECT_EQ(std::string(error.what()), "line 1: mtllib packed.mtl: it is zstd-compressed; decompress it first");
    }
}

TEST(ObjReader, FacesOfFewerThanThreeCornersAreRefused) {
    EXPECT_EQ(error_for(kSquare + "f 1 2\n"), "line 5: a face needs 3 corners or more, this one has 2");
    EXPECT_EQ(error_for(kSquare + "f\n"), "line 5: a face needs 3 corners or more, this one has 0");
}

TEST(ObjReader, NumbersMustBeFiniteAndInRange) {
    EXPECT_EQ(error_for("v 0 nan 0\n"), "line 1: 'v': 'nan' is not a finite number");
    EXPECT_EQ(error_for("v 0 0 1e400\n"), "line 1: 'v': '1e400' is not a finite number");
    EXPECT_EQ(error_for("v 0 0 inf\n"), "line 1: 'v': 'inf' is not a finite number");
    EXPECT_EQ(error_for("v 0 0\n"), "line 1: 'v' needs 3 numbers, the line has 2");
    EXPECT_EQ(error_for("v 1 2 3\nvn 0 0 nan\n"), "line 2: 'vn': 'nan' is not a finite number");
    EXPECT_EQ(error_for("vt 0.5 x\n"), "line 1: 'vt': 'x' is not a finite number");
    const std::string message = error_for("v 2e15 0 0\n");
    EXPECT_EQ(message.rfind("line 1: 'v': '2e15' is out of range: ", 0), 0u) << message;
}

// tinyobjloader multiplies the digits by 5^e: "0e500" (zero) came out as NaN, and 400 digits
// before "e-400" (one) as infinity. Such numbers are refused at their line.
TEST(ObjReader, NumbersTheLibraryCannotReadAreRefused) {
    const std::string limits = "(clrender reads numbers of at most 64 characters with an exponent from -300 to 300)";
    EXPECT_EQ(error_for("v -1 1 0e500\n"), "line 1: 'v': '0e500' is too long or its exponent too large " + limits);
    // Too close to zero for a double is finite, and beyond the exponents read ("not a finite
    // number" before).
    EXPECT_EQ(error_for("v 1e-400 0 0\n"), "line 1: 'v': '1e-400' is too long or its exponent too large " + limits);
    EXPECT_EQ(error_for("v 1e-4000 0 0\n"), "line 1: 'v': '1e-4000' is too long or its exponent too large " + limits);
    EXPECT_EQ(error_for("v 0 0 0\nvn 0 0 0E+301\n"), "line 2: 'vn': '0E+301' is too long or its exponent too large " + limits);
    const std::string one = "1" + std::string(400, '0') + "e-400";
    EXPECT_EQ(error_for("v 0 " + one + " 0\n"),
              "line 1: 'v': '" + one.substr(0, 40) + "...' is too long or its exponent too large " + limits);
    // The limits themselves are read (64 characters: "1", 59 zeros, "e-59").
    TempFolder folder;
    const std::string longest = "1" + std::string(59, '0') + "e-59";
    const ObjMesh mesh = read_obj(folder.write("mesh.obj", "v 1e-300 0E+300 " + longest + "\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_EQ(mesh.positions[0].x, 1e-300);
    EXPECT_EQ(mesh.positions[0].y, 0.0);
    EXPECT_NEAR(mesh.positions[0].z, 1.0, 1e-12);
}

// The checks read numbers correctly rounded; tinyobjloader, which builds the mesh, rounds long
// ones its own way. Where it reads a number the checks passed as out of range or not finite,
// the file is refused at that line (the message named a position's number, not its line).
TEST(ObjReader, ANumberTheLibraryRoundsOutOfRangeIsRefusedAtItsLine) {
    EXPECT_EQ(error_for("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 9.99999999999999999999929928e14 0 0\nf 1 2 3\n"),
              "line 4: 'v 9.99999999999999999999929928e14 0 0': tinyobjloader, which builds the mesh, reads it as "
              "1000000000000000.4 0 0 (it rounds long numbers its own way): every coordinate must be from -1e15 to "
              "1e15; write its numbers with fewer digits");
    EXPECT_EQ(error_for(kSquare + "# a normal no face uses\nvn 0 0 1\n"
                                  "vn 1797693134862315719757487.019526420276742048e284 0 1\nf 1 2 3\n"),
              "line 7: 'vn 1797693134862315719757487.019526420276742048e284 0 1': tinyobjloader, which builds the "
              "mesh, reads it as not finite (its arithmetic overflows near the largest number); write its numbers "
              "with fewer digits");
    // Written short, the same number is read.
    TempFolder folder;
    EXPECT_EQ(read_obj(folder.write("mesh.obj", "v 1e15 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).positions[0].x, 1e15);
}

// The material's Kd is the mesh colour: three numbers, finite and within the colour range.
TEST(ObjReader, MaterialColoursAreCheckedAtTheirLine) {
    const auto error_with = [](const std::string& material) {
        return material_error("# colours\nnewmtl red\n" + material + "\n", "red");
    };
    EXPECT_EQ(error_with("Kd 0e500 0 0"), "line 1: mtllib m.mtl: line 3: 'Kd': '0e500' is too long or its exponent too "
                                          "large (clrender reads numbers of at most 64 characters with an exponent "
                                          "from -300 to 300)");
    EXPECT_EQ(error_with("Kd nan 0 0"), "line 1: mtllib m.mtl: line 3: 'Kd': 'nan' is not a finite number");
    EXPECT_EQ(error_with("Kd 0.5"), "line 1: mtllib m.mtl: line 3: 'Kd' needs 3 numbers (r g b), the line has 1");
    EXPECT_EQ(error_with("Kd spectral red.rfl 1"),
              "line 1: mtllib m.mtl: line 3: 'Kd': 'spectral' is not a finite number");
    EXPECT_EQ(error_with("Kd 0 2e6 0"),
              "line 1: mtllib m.mtl: line 3: 'Kd': '2e6' is out of range: a colour lies from -1e6 to 1e6");
    EXPECT_EQ(error_with("Kd 0 1.5 -0.25"), "");  // outside [0, 1] is a colour, as in a scene
}

// tinyobjloader counts a face's corners in a byte: a polygon of 256 corners would be read as
// another one. The checks refuse it at its line; 255 corners fan as any polygon.
TEST(ObjReader, FacesOfMoreThan255CornersAreRefused) {
    const auto polygon = [](int corners) {
        std::string text;
        for (int i = 0; i < corners; ++i) {
            const double angle = 6.283185307179586 * i / corners;
            text += "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
        }
        text += "f";
        for (int i = 1; i <= corners; ++i) text += " " + std::to_string(i);
        return text + "\n";
    };
    TempFolder folder;
    const ObjMesh largest = read_obj(folder.write("255.obj", polygon(255)));
    EXPECT_EQ(largest.faces, 1u);
    ASSERT_EQ(largest.triangles.size(), 253u);
    EXPECT_EQ(largest.triangles.back(), (Triangle{0, 253, 254}));
    for (int corners : {256, 1000}) {
        EXPECT_EQ(error_for(polygon(corners)), "line " + std::to_string(corners + 1) +
                                                   ": a face has at most 255 corners (tinyobjloader's limit), this one has " +
                                                   std::to_string(corners) + ": split it into smaller faces");
    }
}

TEST(ObjReader, TheTriangleLimitIsCountedAsTheFacesFan) {
    ObjTextProblem problem;
    const std::string text = kSquare + "f 1 2 3\nf 1 2 3 4\n";  // 1 + 2 triangles
    EXPECT_EQ(check_obj_text(text, 3, problem).triangles, 3u);
    EXPECT_EQ(problem.line, 0u);
    check_obj_text(text, 2, problem);
    EXPECT_EQ(problem.line, 6u);
    EXPECT_EQ(problem.detail, "the faces up to this line make 3 triangles, more than the limit of 2");
}

// A text of several MiB is checked in pieces, one per CPU (obj_text_checks.cpp): the counts,
// the line numbers and the first problem must be those of the file as a whole, with relative
// indices and the triangle limit reaching across the pieces.
class LongObjText : public ::testing::Test {
protected:
    // kGroups groups of 4 lines (lines 4g+2 .. 4g+5, after a first face at line 1 that names
    // the last position): three positions and a face of them named back from the latest.
    static constexpr std::uint64_t kGroups = 150000;
    static std::string text(const std::string& replaced_line = "", std::uint64_t at = 0) {
        std::string out = "f 1 2 " + std::to_string(3 * kGroups) + "\n";
        for (std::uint64_t g = 0; g < kGroups; ++g) {
            const std::string k = std::to_string(g);
            out += "v " + k + " 0 0\nv " + k + " 1 0\nv " + k + " 0 1\n";
            out += (at == 4 * g + 5 ? replaced_line : "f -3 -2 -1") + "\n";
        }
        return out;
    }
    static std::uint64_t face_line(std::uint64_t group) { return 4 * group + 5; }
};

TEST_F(LongObjText, CountsAndRelativeIndicesAcrossPieces) {
    const std::string whole = text();
    ASSERT_GT(whole.size(), 4u << 20) << "long enough to be checked in pieces";
    ObjTextProblem problem;
    const ObjTextCounts counts = check_obj_text(whole, kGroups + 1, problem);
    EXPECT_EQ(problem.line, 0u) << problem.detail;
    EXPECT_EQ(counts.positions, 3 * kGroups);
    EXPECT_EQ(counts.faces, kGroups + 1);
    EXPECT_EQ(counts.triangles, kGroups + 1);
    // Back from the last group's face to the very first position: every position precedes it.
    const std::uint64_t last = kGroups - 1;
    const std::string first = "-" + std::to_string(3 * kGroups);
    check_obj_text(text("f " + first + " -2 -1", face_line(last)), kGroups + 1, problem);
    EXPECT_EQ(problem.line, 0u) << problem.detail;
    const std::string beyond = "-" + std::to_string(3 * kGroups + 1);
    check_obj_text(text("f " + beyond + " -2 -1", face_line(last)), kGroups + 1, problem);
    EXPECT_EQ(problem.line, face_line(last));
    EXPECT_EQ(problem.detail, "corner 1: position index " + beyond + " is out of range: " +
                                  std::to_string(3 * kGroups) + " precede this line");
}

TEST_F(LongObjText, TheFirstProblemIsReportedWhereverItLies) {
    ObjTextProblem problem;
    for (std::uint64_t group : {std::uint64_t{2}, kGroups / 2 + 7, kGroups - 1}) {
        check_obj_text(text("f 1 2 0", face_line(group)), kGroups + 1, problem);
        EXPECT_EQ(problem.line, face_line(group));
        EXPECT_EQ(problem.detail, "corner 3: position index 0: indices count from 1 (or back from -1)");
    }
    // Two bad lines, far apart: the first is reported.
    std::string two = text("v 1 nan 0", face_line(3));
    const std::size_t late = two.rfind("f -3 -2 -1");
    two.replace(late, 10, "f 1 2");
    check_obj_text(two, kGroups + 1, problem);
    EXPECT_EQ(problem.line, face_line(3));
    EXPECT_EQ(problem.detail, "'v': 'nan' is not a finite number");
    // The triangle limit, crossed late in the file: named at the face that crosses it.
    // The first face, then one a group: group g's face makes g + 2 triangles.
    const std::uint64_t limit = kGroups - 10;
    check_obj_text(text(), limit, problem);
    EXPECT_EQ(problem.line, face_line(limit - 1));
    EXPECT_EQ(problem.detail, "the faces up to this line make " + std::to_string(limit + 1) +
                                  " triangles, more than the limit of " + std::to_string(limit));
}

TEST(ObjReader, FilesThatAreNotMeshesAreRefusedAtOnce) {
    TempFolder folder;
    try {
        read_obj(folder.file("missing.obj"));
        ADD_FAILURE() << "a missing file was read";
    } catch (const ObjError& error) {
        EXPECT_NE(std::string(error.what()).find("no such file"), std::string::npos) << error.what();
    }
    EXPECT_THROW(read_obj(folder.path()), ObjError);  // a folder
    const std::string fifo = folder.file("pipe.obj");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THROW(read_obj(fifo), ObjError);  // no writer: refused, not waited for
    EXPECT_THROW(read_obj("/dev/zero"), ObjError);
    // A file beyond the limit is refused by its size, before a byte is read (a sparse file).
    const std::string huge = folder.write("huge.obj", "");
    ASSERT_EQ(::truncate(huge.c_str(), static_cast<off_t>(kMaxObjFileBytes + 1)), 0);
    try {
        read_obj(huge);
        ADD_FAILURE() << "a file beyond the limit was read";
    } catch (const ObjError& error) {
        EXPECT_NE(std::string(error.what()).find("more than the limit of 1 GiB"), std::string::npos) << error.what();
    }
}

// Statements clrender does not draw reach no parser: a skin weight of 1e400 once reached
// tinyobjloader's conversion to int (undefined behaviour, found by the OBJ fuzzer), and a
// .mtl's other statements are not parsed either.
TEST(ObjReader, StatementsThatAreNotDrawnAreIgnored) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl red\nillum 99999999999999999999\n-texres 1e400\nKd 0.5 0.25 1\nmap_Kd -s 1e400 x.png\n");
    const ObjMesh mesh = read_obj(folder.write(
        "mesh.obj", "mtllib m.mtl\n" + kSquare + "vw 0 1e400 1\nl 1 2 99\np 0\nt crease 99999999/1/0 1 2\n"
                    "curv 0 1 1 2\nusemtl red\nf 1 2 3\n"));
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}}));
    EXPECT_EQ(mesh.diffuse, (std::optional<Vec3>{Vec3{0.5, 0.25, 1}}));
    // Lines keep their numbers for the library's own messages.
    EXPECT_EQ(obj_statements_used("v 1 2 3\r\nvw 0 1e400\rf 1 1 1"), "v 1 2 3\n\nf 1 1 1\n");
}

TEST(ObjReader, AnEmptyFileIsAnEmptyMesh) {
    TempFolder folder;
    const ObjMesh mesh = read_obj(folder.write("empty.obj", "# nothing\n"));
    EXPECT_EQ(mesh.faces, 0u);
    EXPECT_TRUE(mesh.triangles.empty());
}

// A mesh takes one colour: a later material whose Kd differs from the first face's is a
// warning with its line, counting the other lines that use such materials; one of the same Kd,
// or without a Kd, is none.
TEST(ObjReader, AMaterialWhoseColourTheMeshDoesNotTakeIsAWarning) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\nnewmtl crimson\nKd 1 0 0\nnewmtl plain\n");
    const ObjMesh mesh = read_obj(folder.write(
        "mesh.obj", "mtllib m.mtl\n" + kSquare + "usemtl red\nf 1 2 3\nusemtl blue\nf 1 3 4\nusemtl red\nf 1 2 4\n"
                    "usemtl blue\nf 2 3 4\n"));
    EXPECT_EQ(mesh.diffuse, (Vec3{1, 0, 0}));
    EXPECT_EQ(mesh.warnings, (std::vector<std::string>{
                                 "line 8: usemtl blue: a mesh takes one colour, the scene's ambient or else its first "
                                 "face's material's Kd; this material's Kd is not used (nor those of 1 more usemtl "
                                 "lines)"}));
    EXPECT_TRUE(read_obj(folder.write("same.obj", "mtllib m.mtl\n" + kSquare +
                                                      "usemtl red\nf 1 2 3\nusemtl crimson\nf 1 3 4\nusemtl plain\nf 1 2 4\n"))
                    .warnings.empty());
}

// A mesh takes one colour: the texture map (map_Kd) of a material it uses is not drawn, which
// a warning says with the .mtl's line (it was read past in silence), counting the other used
// materials with one; a texture of a material no usemtl uses, or one before any newmtl, is none.
TEST(ObjReader, ATextureMapTheMeshDoesNotDrawIsAWarning) {
    TempFolder folder;
    folder.write("m.mtl", "map_Kd stray.png\nnewmtl wood\nKd 1 1 1\nmap_Kd -s 2 2 1 wood.png\nmap_Kd again.png\n"
                          "newmtl plain\nKd 1 0 0\nnewmtl stone\nmap_Kd stone.png\nnewmtl unused\nmap_Kd unused.png\n");
    const ObjMesh mesh = read_obj(folder.write(
        "mesh.obj", "mtllib m.mtl\n" + kSquare + "usemtl wood\nf 1 2 3\nusemtl stone\nf 1 3 4\n"));
    EXPECT_EQ(mesh.diffuse, (Vec3{1, 1, 1}));
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0], "mtllib m.mtl: line 4: map_Kd -s 2 2 1 wood.png: a mesh takes one colour, the scene's "
                                "ambient or else its first face's material's Kd; this texture is not drawn (nor those "
                                "of 1 more materials it uses)");
    EXPECT_TRUE(read_obj(folder.write("plain.obj", "mtllib m.mtl\n" + kSquare + "usemtl plain\nf 1 2 3\n")).warnings.empty());
}

// tinyobjloader matches .mtl statements case for case: "KD 1 0 0" or "Newmtl red" was skipped in
// silence, the mesh drawn grey. A warning names the first such line of each .mtl the OBJ uses
// and counts the rest; the statements clrender does not read (Ka, Ns, illum) in any case are no
// such lines, nor is a word that only begins like one.
TEST(ObjReader, AMtlStatementWrittenInAnotherCaseIsAWarning) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl red\nKD 1 0 0\nka 1 1 1\nILLUM 2\nkd 0 1 0\nKds 1 1 1\nMAP_KD red.png\n");
    const ObjMesh mesh = read_obj(folder.write("mesh.obj", "mtllib m.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n"));
    EXPECT_EQ(mesh.diffuse, std::nullopt) << "the line is ignored, as tinyobjloader does";
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0], "mtllib m.mtl: line 2: 'KD' is not a .mtl statement (statements are case-sensitive: "
                                "'Kd'): the line is ignored (and 2 more such lines)");
    folder.write("n.mtl", "Newmtl blue\nKd 0 0 1\n");
    const ObjMesh undefined = read_obj(folder.write("blue.obj", "mtllib n.mtl\n" + kSquare + "usemtl blue\nf 1 2 3\n"));
    ASSERT_EQ(undefined.warnings.size(), 2u) << "after the warning that no .mtl defines 'blue'";
    EXPECT_EQ(undefined.warnings[1], "mtllib n.mtl: line 1: 'Newmtl' is not a .mtl statement (statements are "
                                     "case-sensitive: 'newmtl'): the line is ignored");
    folder.write("n2.mtl", "Newmtl blue\nKd 0 0 1\nnewmtl red\n");  // the Kd belongs to no material
    const std::vector<std::string> two =
        read_obj(folder.write("n2.obj", "mtllib n2.mtl\n" + kSquare + "f 1 2 3\n")).warnings;
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0].rfind("mtllib n2.mtl: line 1: 'Newmtl' is not a .mtl statement", 0), 0u) << two[0];
    EXPECT_EQ(two[1].rfind("mtllib n2.mtl: line 2: a Kd before the first newmtl", 0), 0u) << two[1];
    folder.write("ok.mtl", "newmtl red\nKa 1 1 1\nillum 2\nKd 1 0 0\n");
    EXPECT_TRUE(read_obj(folder.write("ok.obj", "mtllib ok.mtl\n" + kSquare + "usemtl red\nf 1 2 3\n")).warnings.empty());
}

// 600,000 positions, then `tail` from line 600,001: a text of more than 4 MiB, which the checks
// read in parts.
std::string checked_in_parts(const std::string& tail) {
    std::string text;
    for (int i = 0; i < 600000; ++i) text += "v 0 0 0\n";
    return text + tail;
}

// A line whose first word is no OBJ statement is skipped by tinyobjloader in silence: a `v` line
// behind the byte order mark of a file joined on (or written "V") shifted every later face onto
// other positions, with no word. A warning names the first such line and counts the rest; the
// statements of the format that clrender does not draw (l, p, vp, curves) are no such lines.
TEST(ObjReader, ALineThatIsNoObjStatementIsAWarning) {
    const ObjMesh joined = parse_obj("v 0 0 0\n\xEF\xBB\xBFv 1 0 0\nv 0 1 0\nv 1 1 0\nF 1 2 3\nf 1 2 3\n", "mesh.obj");
    EXPECT_EQ(joined.positions.size(), 3u) << "the line behind the mark is not read";
    ASSERT_EQ(joined.warnings.size(), 1u);
    EXPECT_EQ(joined.warnings[0], "line 2: '\\xEF\\xBB\\xBFv' is not an OBJ statement: the line is ignored (and 1 more such "
                                  "lines)");
    EXPECT_TRUE(parse_obj(kSquare + "l 1 2\np 1\nvp 0.5\ncstype bezier\ns off\no a\ng b\nf 1 2 3\n", "mesh.obj")
                    .warnings.empty());
    // In a text checked in parts (4 MiB and more), the line is counted from the file's start.
    const std::string large = checked_in_parts("v 1 0 0\nv 0 1 0\nvv 1 1 1\nf -3 -2 -1\nvv 2 2 2\n");
    ASSERT_GT(large.size(), std::size_t(4) << 20);
    const ObjMesh parted = parse_obj(large, "large.obj");
    ASSERT_EQ(parted.warnings.size(), 1u);
    EXPECT_EQ(parted.warnings[0], "line 600003: 'vv' is not an OBJ statement: the line is ignored (and 1 more such lines)");
}

// Colours given with the positions (`v x y z r g b`, as MeshLab, Open3D and photogrammetry tools
// write them) were read past in silence: the mesh in grey, exit 0 also with --strict. A mesh
// takes one colour, so a warning names the first such line and counts the rest; a position's
// fourth number (its weight) and numbers behind a '#' are no colour.
TEST(ObjReader, VertexColoursTheMeshDoesNotDrawAreAWarning) {
    const ObjMesh coloured =
        parse_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0 0 1 0\nf 1 2 3\n", "mesh.obj");
    ASSERT_EQ(coloured.warnings.size(), 1u);
    EXPECT_EQ(coloured.warnings[0], "line 1: a vertex colour after the position (v x y z r g b): a mesh takes one "
                                    "colour, the scene's ambient or else its first face's material's Kd; the "
                                    "vertices' colours are not drawn (nor those of 2 more such lines)");
    EXPECT_TRUE(parse_obj("v 0 0 0 1\nv 1 0 0 1\nv 1 1 0 # 1 0 0\nf 1 2 3\n", "mesh.obj").warnings.empty());
    // In a text checked in parts (4 MiB and more), the line is counted from the file's start.
    const std::string large = checked_in_parts("v 1 0 0\nv 0 1 0 1 0 0\nf -3 -2 -1\n");
    ASSERT_GT(large.size(), std::size_t(4) << 20);
    const ObjMesh parted = parse_obj(large, "large.obj");
    ASSERT_EQ(parted.warnings.size(), 1u);
    EXPECT_EQ(parted.warnings[0].substr(0, 14), "line 600002: a");
}

// A polygon is drawn as a fan from its first corner (docs/scene-format.md): a concave one whose
// first corner does not see every other corner (a U started at an outer corner, as exporters
// write n-gons) fanned into triangles outside its outline, which the image drew filled, exit 0
// and no warning. A warning names the first such face's line and counts the rest; convex
// polygons, concave ones whose fan stays inside (a chevron from its inner corner), a corner on
// an edge, a slightly warped quad, and triangles give none.
TEST(ObjReader, APolygonWhoseFanCoversAreaOutsideItIsAWarning) {
    const std::string u = "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv 1 2 0\nv 1 -1 0\nv -1 -1 0\nv -1 2 0\nv -2 2 0\n";
    const ObjMesh outside = parse_obj(u + "# a U\nf 1 2 3\nf 1 2 3 4 5 6 7 8\nf 8 7 6 5 4 3 2 1\n", "u.obj");
    EXPECT_EQ(outside.triangles.size(), 13u);  // still drawn, as documented
    ASSERT_EQ(outside.warnings.size(), 1u);
    EXPECT_EQ(outside.warnings[0], "line 11: a polygon of 8 corners that is not convex as seen from its first corner: "
                                   "it is drawn as a fan from that corner, which covers area outside its outline "
                                   "(and 1 more such faces); triangulate it when exporting, or start it at a corner "
                                   "that sees every other corner");
    // A bow tie's two triangles turn against each other; the fans below stay inside.
    EXPECT_EQ(parse_obj("v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n", "bow.obj").warnings.size(), 1u);
    for (const char* fine : {"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",                         // square
                             "v 0 0 0\nv -2 -2 0\nv 0 2 0\nv 2 -2 0\nf 1 2 3 4\n",                      // chevron
                             "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nf 1 2 3 4 5\n",              // on an edge
                             "v 0 0 0\nv 1 0 0.1\nv 1 1 0\nv 0 1 0.1\nf 1 2 3 4\n",                      // warped
                             "v 0 0 0\nv 1e-15 0 0\nv 1e-15 1e-15 0\nv 0 1e-15 0\nf 4 3 2 1\n"}) {     // tiny
        const ObjMesh mesh = parse_obj(fine, "fine.obj");
        EXPECT_TRUE(mesh.warnings.empty()) << fine << mesh.warnings.front();
    }
}

// Each material and .mtl name is kept once however many lines repeat it: a file of millions of
// `usemtl` lines took 400 MB for 48 MiB of text.
TEST(ObjReader, RepeatedMaterialStatementsAreKeptOnce) {
    std::string text = "mtllib a.mtl b.mtl\n";
    for (int i = 0; i < 1000; ++i) text += "usemtl x\nmtllib b.mtl a.mtl\nusemtl y\n";
    text += "f 1 2 3\nusemtl x\n";
    const ObjMaterialStatements statements = material_statements(text);
    ASSERT_EQ(statements.libraries.size(), 2u);
    EXPECT_EQ(statements.libraries[0].name, "a.mtl");
    EXPECT_EQ(statements.libraries[0].line, 1u);
    EXPECT_EQ(statements.libraries[1].name, "b.mtl");
    EXPECT_EQ(statements.libraries[1].line, 1u);
    ASSERT_EQ(statements.uses.size(), 2u);
    EXPECT_EQ(statements.uses[0].name, "x");
    EXPECT_EQ(statements.uses[0].first_line, 2u);
    EXPECT_EQ(statements.uses[0].lines, 1001u);
    EXPECT_EQ(statements.uses[1].name, "y");
    EXPECT_EQ(statements.uses[1].first_line, 4u);
    EXPECT_EQ(statements.uses[1].lines, 1000u);
    EXPECT_EQ(statements.first_face_material, "y");
}

// The parse's memory check counts twice the text, the triangles and each line that may make a
// shape or name a material (tinyobjloader makes a shape at each `o` or `g`: a file of one face
// per object took 530 bytes a triangle, not the 300 counted before).
TEST(ObjReader, ShapesAndMaterialLinesCountTowardsTheParseBudget) {
    TempFolder folder;
    const std::string text = kSquare + "o a\nf 1 2 3\ng b\nf 1 3 4\nusemtl c\nmtllib m.mtl\n";
    folder.write("m.mtl", "newmtl c\nKd 1 0 0\n");
    const std::string path = folder.write("mesh.obj", text);
    const std::uint64_t statement_bytes = std::string("o ag busemtl cmtllib m.mtl").size();
    const std::uint64_t needed = 2 * text.size() + 2 * kParsedTriangleBytes + 4 * kStatementBytes +
                                 statement_bytes * kStatementTextBytes + 4 * kVertexLineBytes;
    EXPECT_EQ(parse_obj(text, path, needed).triangles.size(), 2u);
    EXPECT_THROW(parse_obj(text, path, needed - 1), MeshMemoryError);
}

// ... and the bytes of those lines and of `s` lines, which their names take several times over:
// a 100 MB `usemtl` line peaked at 1.55 GB (`g a a ...` at 2.43 GB) where twice its text, 200 MB,
// had been counted, so that a budget of 1 GB let it be parsed.
TEST(ObjReader, LongNamesCountTowardsTheParseBudgetByTheirLength) {
    const std::string triangle = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n";
    for (const std::string keyword : {"usemtl", "mtllib", "g", "o", "s"}) {
        const std::string line = keyword + " " + std::string(std::size_t(1) << 20, 'a');
        const std::string text = triangle + line + "\n";
        const std::uint64_t statements = keyword == "s" ? 0 : 1;
        const std::uint64_t needed = 2 * text.size() + kParsedTriangleBytes + statements * kStatementBytes +
                                     line.size() * kStatementTextBytes + 3 * kVertexLineBytes;
        try {
            parse_obj(text, "long.obj", needed - 1);
            ADD_FAILURE() << keyword << ": a long line was parsed on a budget one byte short of it";
        } catch (const MeshMemoryError& error) {
            EXPECT_NE(std::string(error.what()).find("(and " + std::to_string(line.size()) +
                                                     " bytes of o, g, s, usemtl and mtllib lines) would take"),
                      std::string::npos)
                << error.what();
        }
        try {
            parse_obj(text, "long.obj", needed);
        } catch (const ObjError&) {  // the .mtl named is missing: the budget passed
        }
    }
}

// ... and each `v`, `vt` and `vn` line: a point cloud or scan with a face took about 60 bytes a
// `v` line besides twice its text (48 MiB of `v 0 0 0` lines: 380 MB, where 96 MB were counted).
TEST(ObjReader, VertexLinesCountTowardsTheParseBudget) {
    std::string text = kSquare + "f 1 2 3\n";
    for (int i = 0; i < 1000; ++i) text += "v 0 0 0\nvt 0 0\nvn 0 0 1\n";
    const std::uint64_t needed = 2 * text.size() + kParsedTriangleBytes + (4 + 3000) * kVertexLineBytes;
    EXPECT_EQ(parse_obj(text, "cloud.obj", needed).positions.size(), 1004u);
    try {
        parse_obj(text, "cloud.obj", needed - 1);
        ADD_FAILURE() << "the parse passed a budget one byte short of its vertex lines";
    } catch (const MeshMemoryError& error) {
        EXPECT_NE(std::string(error.what()).find("its 1 triangles and 3004 v, vt and vn lines would take"), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace clr
