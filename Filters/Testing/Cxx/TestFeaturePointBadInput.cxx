// Bad input gets a warning or an error naming the problem, and a well-defined output: no crash, no
// hang, no huge allocation, no NaN or infinity in any output array.
#include "FeaturePointsTestRun.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCreaseVotingFeatures.h"
#include "vtkFeatureCurveExtraction.h"
#include "vtkFeatureModelSource.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMeshFeatureSampler.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVoxelDensityContrastFilter.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
struct Outcome
{
  vtkSmartPointer<vtkFeaturePointExtraction> Filter;
  std::string Message; // warning or error text
  double Seconds;
};

Outcome Run(vtkPoints* points)
{
  Outcome o;
  o.Filter = vtkSmartPointer<vtkFeaturePointExtraction>::New();
  vtkNew<vtkTest::ErrorObserver> observer;
  o.Filter->AddObserver(vtkCommand::WarningEvent, observer);
  o.Filter->AddObserver(vtkCommand::ErrorEvent, observer);
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  o.Filter->SetInputData(data);
  const auto t0 = std::chrono::steady_clock::now();
  o.Filter->Update();
  o.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.Message = observer->GetWarning() ? observer->GetWarningMessage()
                                     : (observer->GetError() ? observer->GetErrorMessage() : "");
  return o;
}

// The values of `got`'s arrays that differ from those of `expected` at point source(i) (0 where
// source(i) < 0), over got's n points; `arrays` receives the number of expected's arrays (a
// missing or misshapen array counts as one difference).
long DifferingValues(vtkPointData* expected, vtkPointData* got, vtkIdType n,
  const std::function<vtkIdType(vtkIdType)>& source, long& arrays)
{
  long differences = 0;
  arrays = 0;
  for (int k = 0; k < expected->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* x = expected->GetArray(k);
    vtkDataArray* y = x ? got->GetArray(x->GetName()) : nullptr;
    if (!x)
    {
      continue;
    }
    ++arrays;
    if (!y || y->GetNumberOfComponents() != x->GetNumberOfComponents())
    {
      ++differences;
      continue;
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType from = source(i);
      for (int comp = 0; comp < x->GetNumberOfComponents(); ++comp)
      {
        const double want = from < 0 ? 0.0 : x->GetComponent(from, comp);
        differences += y->GetComponent(i, comp) != want ? 1 : 0;
      }
    }
  }
  return differences;
}

vtkSmartPointer<vtkPoints> Copy(vtkPolyData* data)
{
  auto p = vtkSmartPointer<vtkPoints>::New();
  p->DeepCopy(data->GetPoints());
  return p;
}
} // namespace

int TestFeaturePointBadInput(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  auto expect = [&failures](const char* name, const Outcome& o, const char* words, long maxFeatures) {
    vtkPolyData* out = o.Filter->GetOutput();
    const long features = CountSet(Mask(out));
    std::printf("%-22s %.2fs, %ld feature points, message: %s\n", name, o.Seconds, features,
      o.Message.empty() ? "(none)" : o.Message.substr(o.Message.find(':') + 1).c_str());
    FP_CHECK(AllFinite(out), "%s: NaN or infinity in an output array", name);
    FP_CHECK(out->GetNumberOfPoints() == o.Filter->GetInputDataObject(0, 0)
                                            ->GetNumberOfElements(vtkDataObject::POINT),
      "%s: output point count differs from input", name);
    FP_CHECK(features <= maxFeatures, "%s: %ld feature points", name, features);
    if (words)
    {
      FP_CHECK(o.Message.find(words) != std::string::npos, "%s: message lacks '%s': %s", name,
        words, o.Message.c_str());
    }
  };

  {
    vtkNew<vtkPoints> none;
    expect("empty input", Run(none), "no points", 0);
  }
  {
    Cloud few = NoisyPlane(10, 61);
    expect("10 points", Run(Copy(few.Data)), "fewer than the", 0);
  }
  {
    Cloud c = BentPlanes(8000, 62, 90.0);
    auto p = Copy(c.Data);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    p->SetPoint(17, nan, 0.5, 0.0);
    p->SetPoint(4000, 0.1, inf, 0.0);
    p->SetPoint(5000, -inf, nan, inf);
    Outcome o = Run(p);
    expect("NaN / inf coordinates", o, "point 17", 8000);
    FP_CHECK(Mask(o.Filter->GetOutput())->GetValue(17) == 0, "NaN point marked");
    FP_CHECK(CountSet(Mask(o.Filter->GetOutput())) > 20, "features lost around NaN points");
  }
  {
    // Every point three times, and one stack of 40 coincident points.
    Cloud c = NoisyPlane(3000, 63);
    vtkNew<vtkPoints> p;
    p->SetDataTypeToDouble();
    double x[3];
    for (int copy = 0; copy < 3; ++copy)
    {
      for (vtkIdType i = 0; i < c.Data->GetNumberOfPoints(); ++i)
      {
        c.Data->GetPoint(i, x);
        p->InsertNextPoint(x);
      }
    }
    for (int i = 0; i < 40; ++i)
    {
      p->InsertNextPoint(0.5, 0.5, 0.0);
    }
    expect("duplicate points", Run(p), "coincide with another point", 9040);
  }
  {
    vtkNew<vtkPoints> p;
    for (int i = 0; i < 100; ++i)
    {
      p->InsertNextPoint(1.0, 2.0, 3.0);
    }
    expect("all points coincide", Run(p), "All points coincide", 0);
  }
  {
    // More than half the cloud stacked at one position far from the rest (a scanner's invalid
    // returns at its origin): the copies count once in the mean spacing, which stays the
    // plane's. Counted each, the stack's distance to the plane was the median, and the mean
    // spacing about half of it (the plane's features all lost).
    Cloud c = NoisyPlane(3000, 64);
    vtkSmartPointer<vtkPoints> alone = Copy(c.Data);
    vtkSmartPointer<vtkPoints> p = Copy(c.Data);
    for (int i = 0; i < 3100; ++i)
    {
      p->InsertNextPoint(0.5, 0.5, 50.0);
    }
    const Outcome plane = Run(alone);
    const Outcome o = Run(p);
    expect("half the cloud stacked", o, "coincide with another point", 6100);
    FP_CHECK(std::abs(o.Filter->GetMeanSpacing() - plane.Filter->GetMeanSpacing()) <
        0.01 * plane.Filter->GetMeanSpacing(),
      "half the cloud stacked: mean spacing %g, the plane's %g", o.Filter->GetMeanSpacing(),
      plane.Filter->GetMeanSpacing());
  }
  {
    // Two positions, 50,000 copies each: each copy's nearest distinct point used to be searched
    // for on its own, a walk through the whole grid per copy (minutes); now once per position.
    vtkNew<vtkPoints> p;
    for (int i = 0; i < 100000; ++i)
    {
      p->InsertNextPoint(i % 2, 0.0, 0.0);
    }
    Outcome o = Run(p);
    expect("two positions, 50,000 copies each", o, "coincide with another point", 100000);
    FP_CHECK(o.Seconds < 30.0, "two positions, 50,000 copies each: %.1f s", o.Seconds);
  }
  {
    vtkNew<vtkPoints> p;
    for (int i = 0; i < 2000; ++i)
    {
      p->InsertNextPoint(0.001 * i, 0.002 * i, -0.001 * i);
    }
    expect("collinear points", Run(p), "straight line", 2000);
  }
  {
    // A unit cube's surface on a 1/16 lattice, stored as float32 at 1e6, where 1/16 is the unit
    // in the last place: the coordinates resolve the cube exactly, though no better than 16 of
    // those units, and it was called a straight line.
    vtkNew<vtkPoints> p;
    p->SetDataTypeToFloat();
    for (int i = 0; i <= 16; ++i)
    {
      for (int j = 0; j <= 16; ++j)
      {
        for (int k = 0; k <= 16; ++k)
        {
          if (i % 16 == 0 || j % 16 == 0 || k % 16 == 0)
          {
            p->InsertNextPoint(1e6 + i / 16.0, 1e6 + j / 16.0, 1e6 + k / 16.0);
          }
        }
      }
    }
    const Outcome o = Run(p);
    expect("float32 cube at 1e6", o, nullptr, p->GetNumberOfPoints());
    FP_CHECK(o.Message.find("straight line") == std::string::npos &&
        o.Message.find("one plane") == std::string::npos,
      "float32 cube at 1e6: %s", o.Message.c_str());
  }
  {
    // A regular grid on a plane: every score equal, nothing is a feature.
    vtkNew<vtkPoints> p;
    for (int i = 0; i < 100; ++i)
    {
      for (int j = 0; j < 100; ++j)
      {
        p->InsertNextPoint(0.01 * i, 0.01 * j, 0.0);
      }
    }
    expect("exact planar grid", Run(p), "one plane", 0);
  }
  {
    Cloud c = BentPlanes(8000, 64, 90.0);
    auto p = Copy(c.Data);
    p->InsertNextPoint(1e30, -1e30, 1e30);
    Outcome o = Run(p);
    expect("huge outlier", o, nullptr, 8001);
    FP_CHECK(o.Seconds < 30.0, "huge outlier: %.1f s", o.Seconds);
    FP_CHECK(CountSet(Mask(o.Filter->GetOutput())) > 20, "features lost next to an outlier");
  }
  {
    // A point near the largest double: its distance to every other point overflows, so it has no
    // nearest point, but it coincides with none either.
    Cloud c = BentPlanes(8000, 65, 90.0);
    vtkNew<vtkPoints> p;
    p->SetDataTypeToDouble();
    double x[3];
    for (vtkIdType i = 0; i < c.Data->GetNumberOfPoints(); ++i)
    {
      c.Data->GetPoint(i, x);
      p->InsertNextPoint(x);
    }
    p->InsertNextPoint(1e308, 1e308, 1e308);
    Outcome o = Run(p);
    expect("point at 1e308", o, nullptr, 8001);
    FP_CHECK(o.Message.find("coincide") == std::string::npos, "point at 1e308: %s",
      o.Message.c_str());
  }
  {
    // Two bent sheets 1e12 apart: the cloud's covariance is the separation's, yet its points lie
    // on no line or plane (the coordinates resolve 1e-4 there).
    Cloud c = BentPlanes(8000, 66, 90.0);
    vtkNew<vtkPoints> p;
    p->SetDataTypeToDouble();
    double x[3];
    for (vtkIdType i = 0; i < 8000; ++i)
    {
      c.Data->GetPoint(i, x);
      const double shift = i < 4000 ? 1e12 : 0.0;
      p->InsertNextPoint(x[0] + shift, x[1] + shift, x[2]);
    }
    Outcome o = Run(p);
    expect("two sheets 1e12 apart", o, nullptr, 8000);
    // The same with both sheets flat, on one plane: that is one plane.
    vtkNew<vtkPoints> flat;
    flat->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < 8000; ++i)
    {
      c.Data->GetPoint(i, x);
      const double shift = i < 4000 ? 1e12 : 0.0;
      flat->InsertNextPoint(x[0] + shift, x[1] + shift, 0.0);
    }
    Outcome coplanar = Run(flat);
    FP_CHECK(coplanar.Message.find("one plane") != std::string::npos,
      "two flat sheets 1e12 apart on one plane: %s", coplanar.Message.c_str());
    FP_CHECK(o.Message.find("straight line") == std::string::npos &&
        o.Message.find("one plane") == std::string::npos,
      "two sheets 1e12 apart: %s", o.Message.c_str());
  }
  // Clouds of 65536 points and more go through the voxel screen's spatial sample first: NaN
  // points, stacks of duplicates and a far outlier together must not upset it.
  for (const double factor : { 1.0, 3.0 })
  {
    Cloud c = BentPlanes(80000, factor > 1.0 ? 66 : 65, 90.0, 0.5, factor);
    auto p = Copy(c.Data);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (vtkIdType i = 0; i < 80000; i += 800)
    {
      p->SetPoint(i, nan, 0.0, nan);
    }
    double x[3];
    for (vtkIdType i = 1; i < 80000; i += 40)
    {
      p->GetPoint(i, x);
      for (int copy = 0; copy < 3; ++copy)
      {
        p->InsertNextPoint(x);
      }
    }
    p->InsertNextPoint(1e30, -1e30, 1e30);
    Outcome o = Run(p);
    const char* name = factor > 1.0 ? "large, denser, mixed" : "large, uniform, mixed";
    expect(name, o, "NaN", p->GetNumberOfPoints());
    FP_CHECK(o.Seconds < 60.0, "%s: %.1f s", name, o.Seconds);
    FP_CHECK(CountSet(Mask(o.Filter->GetOutput())) > 100, "%s: features lost", name);
    FP_CHECK(Mask(o.Filter->GetOutput())->GetValue(800) == 0, "%s: NaN point marked", name);
  }
  // NaN points change nothing for the others: the detectors renumber the valid points in space
  // and put their arrays back in the input's order, so a cloud with NaN points interleaved must
  // give every valid point exactly (bit for bit) the arrays of the same cloud without them, and
  // the NaN points zeros. Both the paper's method (voxel screen and voxel step: 80000 points,
  // features denser) and the default crease detector.
  {
    Cloud c = BentPlanes(80000, 67, 90.0, 0.5, 3.0);
    auto clean = Copy(c.Data);
    vtkNew<vtkPoints> mixed;
    mixed->SetDataTypeToDouble();
    std::vector<vtkIdType> cleanOf; // for each mixed point, its clean id (-1: NaN)
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (vtkIdType i = 0; i < clean->GetNumberOfPoints(); ++i)
    {
      if (i % 97 == 3)
      {
        mixed->InsertNextPoint(nan, 1.0, nan);
        cleanOf.push_back(-1);
      }
      mixed->InsertNextPoint(clean->GetPoint(i));
      cleanOf.push_back(i);
    }
    for (int method = 0; method < 2; ++method)
    {
      vtkSmartPointer<vtkFeaturePointDetector> a, b;
      if (method == 0)
      {
        a = vtkSmartPointer<vtkFeaturePointExtraction>::New();
        b = vtkSmartPointer<vtkFeaturePointExtraction>::New();
      }
      else
      {
        a = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
        b = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
      }
      vtkNew<vtkTest::ErrorObserver> observer; // b warns about its NaN points
      b->AddObserver(vtkCommand::WarningEvent, observer);
      vtkNew<vtkPolyData> da, db;
      da->SetPoints(clean);
      db->SetPoints(mixed);
      a->SetInputData(da);
      b->SetInputData(db);
      a->Update();
      b->Update();
      long arrays = 0;
      const long differences = DifferingValues(a->GetOutput()->GetPointData(),
        b->GetOutput()->GetPointData(), static_cast<vtkIdType>(cleanOf.size()),
        [&cleanOf](vtkIdType i) { return cleanOf[i]; }, arrays);
      const long features = CountSet(Mask(b->GetOutput()));
      std::printf("%-22s %s: %ld arrays, %ld values differ from the clean cloud's, %ld feature "
                  "points\n",
        "NaN points interleaved", method == 0 ? "huang2023" : "crease", arrays, differences,
        features);
      FP_CHECK(arrays >= 3 && differences == 0 && features > 100 &&
          features == CountSet(Mask(a->GetOutput())) && observer->GetWarning(),
        "NaN points interleaved (%s): %ld values differ", method == 0 ? "huang2023" : "crease",
        differences);
    }
  }
  // Copies: the default detector scores the distinct positions, so a cloud with every point
  // followed by a copy of it, exact or moved by a millionth of the spacing (a scan merged with a
  // rounded copy of itself), gives both points exactly (bit for bit) the cloud's own arrays, and
  // its mean spacing. Scored as they were, exact copies halved the neighbourhoods' reach and near
  // ones set the mean spacing to their distance.
  {
    Cloud c = BentPlanes(20000, 68, 90.0, 0.5, 3.0);
    auto clean = Copy(c.Data);
    vtkNew<vtkCreaseVotingFeatures> a;
    vtkNew<vtkPolyData> da;
    da->SetPoints(clean);
    a->SetInputData(da);
    a->Update();
    const double s = a->GetMeanSpacing();
    for (double shift : { 0.0, 1e-6 })
    {
      vtkNew<vtkPoints> twins;
      twins->SetDataTypeToDouble();
      double x[3];
      for (vtkIdType i = 0; i < clean->GetNumberOfPoints(); ++i)
      {
        clean->GetPoint(i, x);
        twins->InsertNextPoint(x);
        twins->InsertNextPoint(x[0] + shift * s, x[1] - shift * s, x[2] + shift * s);
      }
      vtkNew<vtkCreaseVotingFeatures> b;
      vtkNew<vtkTest::ErrorObserver> observer;
      b->AddObserver(vtkCommand::WarningEvent, observer);
      vtkNew<vtkPolyData> db;
      db->SetPoints(twins);
      b->SetInputData(db);
      b->Update();
      long arrays = 0;
      const long differences = DifferingValues(a->GetOutput()->GetPointData(),
        b->GetOutput()->GetPointData(), twins->GetNumberOfPoints(),
        [](vtkIdType i) { return i / 2; }, arrays);
      const long features = CountSet(Mask(b->GetOutput()));
      std::printf("%-22s shift %g s: %ld arrays, %ld values differ from the cloud's, %ld "
                  "feature points (the cloud: %ld), mean spacing %g (the cloud: %g)\n",
        "every point twice", shift, arrays, differences, features, CountSet(Mask(a->GetOutput())),
        b->GetMeanSpacing(), s);
      FP_CHECK(arrays >= 5 && differences == 0 && features == 2 * CountSet(Mask(a->GetOutput())) &&
          features > 100 && b->GetMeanSpacing() == s,
        "every point twice (shift %g s): %ld values differ, mean spacing %g against %g", shift,
        differences, b->GetMeanSpacing(), s);
      FP_CHECK(observer->GetWarning() &&
          observer->GetWarningMessage().find("distinct positions") != std::string::npos,
        "every point twice (shift %g s): no warning about the copies", shift);
    }
  }
  // Misshapen arrays and arguments through the API (found by fuzzing the Python wrapping): each
  // crashed or read past an array's end.
  {
    Cloud c = BentPlanes(3000, 64, 90.0);
    for (vtkIdType tuples : { 0, 3 })
    {
      // A point array shorter than the cloud, with OutputFeaturesOnly: left out with a warning
      // (it was copied by the feature points' ids: a crash with 0 tuples, garbage with 3).
      vtkNew<vtkPolyData> data;
      data->DeepCopy(c.Data);
      vtkNew<vtkFloatArray> extra;
      extra->SetName("Extra");
      extra->SetNumberOfTuples(tuples);
      extra->Fill(2.0);
      data->GetPointData()->AddArray(extra);
      vtkNew<vtkCreaseVotingFeatures> detector;
      vtkNew<vtkTest::ErrorObserver> observer;
      detector->AddObserver(vtkCommand::WarningEvent, observer);
      detector->OutputFeaturesOnlyOn();
      detector->SetInputData(data);
      detector->Update();
      vtkPolyData* out = detector->GetOutput();
      std::printf("%-22s %lld tuples: %lld feature points, 'Extra' %s\n", "a short point array",
        static_cast<long long>(tuples), static_cast<long long>(out->GetNumberOfPoints()),
        out->GetPointData()->GetArray("Extra") ? "kept" : "left out");
      FP_CHECK(out->GetNumberOfPoints() > 100 && !out->GetPointData()->GetArray("Extra") &&
          AllFinite(out),
        "a point array of %lld tuples: %lld feature points, or the array was kept",
        static_cast<long long>(tuples), static_cast<long long>(out->GetNumberOfPoints()));
      FP_CHECK(observer->GetWarning() &&
          observer->GetWarningMessage().find("'Extra' has") != std::string::npos,
        "a point array of %lld tuples: no warning", static_cast<long long>(tuples));
    }

    // SelectFeaturePoints with a mask shorter than the cloud, or no cloud: nothing selected.
    vtkNew<vtkUnsignedCharArray> shortMask;
    shortMask->SetNumberOfValues(5);
    shortMask->Fill(1);
    vtkNew<vtkPolyData> selected;
    vtkFeaturePointDetector::SelectFeaturePoints(c.Data, shortMask, selected);
    FP_CHECK(selected->GetNumberOfPoints() == 0, "a 5-value mask selected %lld points",
      static_cast<long long>(selected->GetNumberOfPoints()));
    vtkFeaturePointDetector::SelectFeaturePoints(nullptr, shortMask, selected);
    vtkFeaturePointDetector::SelectFeaturePoints(c.Data, shortMask, nullptr);

    // Stages of a filter that never ran.
    vtkNew<vtkCreaseVotingFeatures> idle;
    FP_CHECK(idle->GetStageName(0) == nullptr && idle->GetStageName(-1) == nullptr &&
        idle->GetStageTime(3) == 0.0,
      "the stages of a filter that never ran");

    // The curves over a detector's output whose arrays are misshapen: the optional ones are left
    // aside with a warning, a FeatureMask of two components is refused with one error.
    vtkNew<vtkCreaseVotingFeatures> detector;
    detector->SetInputData(c.Data);
    detector->Update();
    auto curvesOf = [&](const char* name, int components, vtkIdType tuples, std::string& text) {
      vtkNew<vtkPolyData> data;
      data->DeepCopy(detector->GetOutput());
      vtkNew<vtkFloatArray> bad;
      bad->SetName(name);
      bad->SetNumberOfComponents(components);
      bad->SetNumberOfTuples(tuples);
      bad->Fill(1.0);
      data->GetPointData()->RemoveArray(name);
      data->GetPointData()->AddArray(bad);
      if (std::string(name) == "CreaseVotes")
      {
        data->GetPointData()->SetActiveScalars(name); // the detector's score
      }
      vtkNew<vtkFeatureCurveExtraction> curves;
      vtkNew<vtkTest::ErrorObserver> observer;
      curves->AddObserver(vtkCommand::WarningEvent, observer);
      curves->AddObserver(vtkCommand::ErrorEvent, observer);
      curves->SetInputData(data);
      curves->Update();
      text = observer->GetError() ? observer->GetErrorMessage()
                                  : (observer->GetWarning() ? observer->GetWarningMessage() : "");
      return curves->GetNumberOfCurves();
    };
    std::string text;
    for (const char* name : { "Normals", "FeatureType", "CreaseAngle", "CreaseVotes" })
    {
      const vtkIdType found = curvesOf(name, std::string(name) == "Normals" ? 3 : 1, 0, text);
      std::printf("%-22s '%s' of 0 tuples: %lld curves\n", "curves, misshapen", name,
        static_cast<long long>(found));
      FP_CHECK(found > 0 && text.find("not used") != std::string::npos,
        "curves with '%s' of 0 tuples: %lld curves, message: %s", name,
        static_cast<long long>(found), text.c_str());
    }
    const vtkIdType none = curvesOf("FeatureMask", 2, c.Data->GetNumberOfPoints(), text);
    FP_CHECK(none == 0 && text.find("FeatureMask has") != std::string::npos,
      "curves with a FeatureMask of 2 components: %lld curves, message: %s",
      static_cast<long long>(none), text.c_str());

    // Neighbourhoods: a table entry that names no point; a vertex table beyond memory.
    vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
    neighborhoods->Build(c.Data->GetPoints());
    vtkNew<vtkTest::ErrorObserver> observer;
    neighborhoods->AddObserver(vtkCommand::ErrorEvent, observer);
    vtkNew<vtkIdList> ids;
    ids->InsertNextId(0);
    vtkNew<vtkIntArray> table;
    table->SetNumberOfComponents(2);
    table->InsertNextTuple2(1999999, 1);
    FP_CHECK(neighborhoods->ComputeMeanSpacing(ids, table) == 0.0 && observer->GetError() &&
        observer->GetErrorMessage().find("1999999") != std::string::npos,
      "a neighbour table naming point 1999999 of %lld", static_cast<long long>(
                                                            c.Data->GetNumberOfPoints()));
    vtkNew<vtkCellArray> cells;
    FP_CHECK(!vtkPointCloudNeighborhoods::MakeVertexCells(vtkIdType(1) << 40, cells),
      "2^40 vertex cells were made");
  }
  // NaN given to a setter passes vtkSetClampMacro: the run is refused with an error naming it
  // (the scores were NaN before).
  {
    Cloud c = BentPlanes(3000, 66, 90.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    vtkNew<vtkFeaturePointExtraction> paper;
    paper->SetAlpha(nan);
    vtkNew<vtkCreaseVotingFeatures> crease;
    crease->SetMinimumAngle(nan);
    vtkFeaturePointDetector* filters[2] = { paper, crease };
    const char* names[2] = { "Alpha is NaN", "MinimumAngle is NaN" };
    for (int f = 0; f < 2; ++f)
    {
      vtkNew<vtkTest::ErrorObserver> observer;
      filters[f]->AddObserver(vtkCommand::ErrorEvent, observer);
      filters[f]->SetInputData(c.Data);
      filters[f]->Update();
      vtkPolyData* out = filters[f]->GetOutput();
      std::printf("%-22s %s: %lld points out, %ld feature points\n", "a NaN parameter", names[f],
        static_cast<long long>(out->GetNumberOfPoints()), CountSet(Mask(out)));
      FP_CHECK(observer->GetError() &&
          observer->GetErrorMessage().find(names[f]) != std::string::npos && AllFinite(out) &&
          CountSet(Mask(out)) == 0,
        "a NaN parameter (%s): no error, or a non-finite output", names[f]);
    }
  }
  // The same in the other filters: the curves, the model source, the mesh sampler and the voxel
  // screen put NaN in their points or arrays before.
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // Every coordinate and every floating-point value of point and cell data finite.
    auto finite = [](vtkPolyData* out) {
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double x[3];
        out->GetPoint(i, x);
        if (!std::isfinite(x[0] + x[1] + x[2]))
        {
          return false;
        }
      }
      for (vtkFieldData* fd : { static_cast<vtkFieldData*>(out->GetPointData()),
             static_cast<vtkFieldData*>(out->GetCellData()) })
      {
        for (int a = 0; a < fd->GetNumberOfArrays(); ++a)
        {
          vtkDataArray* array = vtkDataArray::SafeDownCast(fd->GetAbstractArray(a));
          for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
          {
            if (!std::isfinite(array->GetVariantValue(i).ToDouble()))
            {
              return false;
            }
          }
        }
      }
      return true;
    };
    auto refused = [&](const char* what, vtkAlgorithm* filter, const char* name,
                     std::initializer_list<vtkPolyData*> outputs) {
      vtkNew<vtkTest::ErrorObserver> observer;
      filter->AddObserver(vtkCommand::ErrorEvent, observer);
      filter->Update();
      bool clean = true;
      for (vtkPolyData* out : outputs)
      {
        clean = clean && finite(out);
      }
      std::printf("%-22s %s: %s\n", "a NaN parameter", what,
        observer->GetError() ? observer->GetErrorMessage().c_str() : "no error");
      FP_CHECK(observer->GetError() &&
          observer->GetErrorMessage().find(name) != std::string::npos && clean,
        "a NaN parameter (%s): no error naming %s, or a non-finite output", what, name);
    };
    vtkNew<vtkCreaseVotingFeatures> crease;
    crease->SetInputData(BentPlanes(3000, 67, 90.0).Data);
    vtkNew<vtkFeatureCurveExtraction> curves;
    curves->SetInputConnection(crease->GetOutputPort());
    curves->SetStepLength(nan);
    refused("curves", curves, "StepLength is NaN", { curves->GetOutput(0), curves->GetOutput(1) });

    vtkNew<vtkFeatureModelSource> model;
    model->SetNumberOfPoints(2000);
    model->SetNoiseFactor(nan);
    refused("model source", model, "NoiseFactor is NaN", { model->GetOutput() });
    vtkNew<vtkFeatureModelSource> moved;
    moved->SetNumberOfPoints(2000);
    moved->SetCenter(0.0, std::numeric_limits<double>::infinity(), 0.0);
    refused("model source", moved, "Center", { moved->GetOutput() });

    vtkNew<vtkPoints> corners; // a tetrahedron's surface
    corners->InsertNextPoint(0, 0, 0);
    corners->InsertNextPoint(1, 0, 0);
    corners->InsertNextPoint(0, 1, 0);
    corners->InsertNextPoint(0, 0, 1);
    vtkNew<vtkCellArray> faces;
    const vtkIdType tri[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
    for (const auto& t : tri)
    {
      faces->InsertNextCell(3, t);
    }
    vtkNew<vtkPolyData> mesh;
    mesh->SetPoints(corners);
    mesh->SetPolys(faces);
    vtkNew<vtkMeshFeatureSampler> sampler;
    sampler->SetInputData(mesh);
    sampler->SetNoiseSigma(nan);
    refused("mesh sampler", sampler, "NoiseSigma is NaN",
      { sampler->GetOutput(0), sampler->GetOutput(1) });

    vtkNew<vtkVoxelDensityContrastFilter> voxels;
    voxels->SetInputData(BentPlanes(3000, 68, 90.0).Data);
    voxels->SetContrastSigmas(nan);
    refused("voxel screen", voxels, "ContrastSigmas is NaN", { voxels->GetOutput() });
  }
  // An unknown search method was ignored without a word.
  {
    vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
    vtkNew<vtkTest::ErrorObserver> observer;
    neighborhoods->AddObserver(vtkCommand::ErrorEvent, observer);
    neighborhoods->SetSearchMethod(7);
    FP_CHECK(observer->GetError() &&
        observer->GetErrorMessage().find("SearchMethod 7") != std::string::npos &&
        neighborhoods->GetSearchMethod() == vtkPointCloudNeighborhoods::GRID,
      "SetSearchMethod(7): no error, or the locator changed");
  }
  // Distinct points 1e200 apart, given to the filter directly: their squared distances overflow,
  // which looked like coincident points, then (a warning that said so) no score at all. Such a
  // cloud now runs scaled by a power of two: the same mask as the cloud at its own scale, and no
  // warning. The voxel screen, a filter of its own, still names the overflow.
  {
    Cloud c = BentPlanes(3000, 65, 90.0);
    vtkNew<vtkPoints> far;
    far->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < c.Data->GetNumberOfPoints(); ++i)
    {
      double x[3];
      c.Data->GetPoint(i, x);
      far->InsertNextPoint(x[0] * 1e200, x[1] * 1e200, x[2] * 1e200);
    }
    const Outcome o = Run(far);
    const Outcome plain = Run(c.Data->GetPoints());
    const long expected = CountSet(Mask(plain.Filter->GetOutput()));
    expect("coordinates near 1e200", o, nullptr, expected);
    long differ = 0;
    for (vtkIdType i = 0; i < far->GetNumberOfPoints(); ++i)
    {
      differ += Mask(o.Filter->GetOutput())->GetValue(i) !=
        Mask(plain.Filter->GetOutput())->GetValue(i);
    }
    FP_CHECK(expected > 0 && differ == 0 && o.Message.empty(),
      "coordinates near 1e200: %ld of %ld mask values differ from the cloud at its scale, "
      "message: %s",
      differ, expected, o.Message.c_str());
    // The voxel screen said "All points coincide" there.
    vtkNew<vtkPolyData> farCloud;
    farCloud->SetPoints(far);
    vtkNew<vtkVoxelDensityContrastFilter> voxels;
    vtkNew<vtkTest::ErrorObserver> observer;
    voxels->AddObserver(vtkCommand::WarningEvent, observer);
    voxels->SetInputData(farCloud);
    voxels->Update();
    std::printf("%-22s voxel screen: %s\n", "coordinates near 1e200",
      observer->GetWarning() ? observer->GetWarningMessage().c_str() : "no warning");
    FP_CHECK(observer->GetWarning() &&
        observer->GetWarningMessage().find("squares of distances underflow or overflow") !=
          std::string::npos &&
        voxels->GetOutput()->GetNumberOfPoints() == far->GetNumberOfPoints(),
      "coordinates near 1e200: the voxel screen does not say why it builds no grid");
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
