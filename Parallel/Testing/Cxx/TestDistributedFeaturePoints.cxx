// vtkDistributedFeaturePoints under mpiexec: every point array of the result (FeatureMask, the
// scores, the normals) must equal, bit for bit, the detector's on the whole cloud in one process,
// for clouds given to the processes as contiguous pieces in input order. Run as
// `mpiexec -n N TestDistributedFeaturePoints N`.
// `TestDistributedFeaturePoints --write FILE N` (one process) writes the cloud with duplicates
// built from an N-point bracket, for the command-line tool's test; `--write-plain FILE N` the
// bracket itself (benchmarks); `--write-plate FILE N` the plate with a hole (density contrast for
// the paper's voxel pre-filter) with a few duplicates. `--compare-pvtp FILE.pvtp REFERENCE N`
// checks a parallel output of N pieces against one process's output REFERENCE (any readable
// format): each piece holds its points in ascending GlobalPointIds, the pieces every point once,
// and every array of the reference is the same at each point's GlobalPointIds.
#include "vtkCreaseVotingFeatures.h"
#include "vtkCurvatureDensityFeatures.h"
#include "vtkDataArray.h"
#include "vtkDistributedFeaturePoints.h"
#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkFieldData.h"
#include "vtkMPIController.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSurfaceVariationFeatures.h"
#include "vtkUnsignedCharArray.h"
#ifdef FEATUREPOINTS_TEST_PVTP
#include "vtkXMLPPolyDataReader.h"
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace
{
// A generated part (the L bracket: convex and concave edges, a shallow crease), noisy. Its bands
// around the features are sampled three times as densely, which the voxel pre-filter of the
// paper's method sees on the plate with a hole.
vtkSmartPointer<vtkPolyData> Bracket(
  vtkIdType n, int model = vtkFeatureModelSource::BRACKET, double noise = -1.0)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  source->SetNumberOfPoints(n);
  source->SetSeed(7);
  if (noise >= 0.0)
  {
    source->SetNoiseFactor(noise);
  }
  source->Update();
  vtkSmartPointer<vtkPolyData> cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(source->GetOutput()->GetPoints());
  return cloud;
}

// The bracket with many duplicates: one point in `every` (4) copied 1 to 5 times, the copies at
// random places in the order, so that stacks straddle the pieces.
vtkSmartPointer<vtkPolyData> WithDuplicates(vtkPolyData* base, int every = 4)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  const vtkIdType n = base->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataType(base->GetPoints()->GetDataType());
  std::vector<vtkIdType> order;
  for (vtkIdType i = 0; i < n; ++i)
  {
    order.push_back(i);
    if (i % every == 0)
    {
      random->Next();
      const int copies = 1 + static_cast<int>(5 * random->GetValue());
      for (int c = 0; c < copies; ++c)
      {
        order.push_back(i);
      }
    }
  }
  for (size_t i = order.size() - 1; i > 0; --i)
  {
    random->Next();
    std::swap(order[i], order[static_cast<size_t>(random->GetValue() * (i + 1)) % (i + 1)]);
  }
  for (vtkIdType i : order)
  {
    points->InsertNextPoint(base->GetPoint(i));
  }
  vtkSmartPointer<vtkPolyData> cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  // A point array that must travel with the points.
  vtkNew<vtkUnsignedCharArray> tag;
  tag->SetName("Tag");
  tag->SetNumberOfValues(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    tag->SetValue(i, static_cast<unsigned char>(i % 251));
  }
  cloud->GetPointData()->AddArray(tag);
  return cloud;
}

// Process `rank`'s contiguous share of the cloud.
vtkSmartPointer<vtkPolyData> Piece(vtkPolyData* cloud, int rank, int nProcs)
{
  const vtkIdType n = cloud->GetNumberOfPoints();
  const vtkIdType first = n * rank / nProcs, last = n * (rank + 1) / nProcs;
  vtkNew<vtkPoints> points;
  points->SetDataType(cloud->GetPoints()->GetDataType());
  points->SetNumberOfPoints(last - first);
  vtkSmartPointer<vtkPolyData> piece = vtkSmartPointer<vtkPolyData>::New();
  piece->GetPointData()->CopyAllocate(cloud->GetPointData(), last - first);
  for (vtkIdType i = first; i < last; ++i)
  {
    points->SetPoint(i - first, cloud->GetPoint(i));
    piece->GetPointData()->CopyData(cloud->GetPointData(), i, i - first);
  }
  piece->SetPoints(points);
  return piece;
}

// The default detector, declared not distributable: the driver runs it on process 0 alone (the
// fallback of a detector whose GetHaloExtent() says no).
class OneProcessCrease : public vtkCreaseVotingFeatures
{
public:
  static OneProcessCrease* New()
  {
    OneProcessCrease* filter = new OneProcessCrease;
    filter->InitializeObjectBase();
    return filter;
  }
  vtkTypeMacro(OneProcessCrease, vtkCreaseVotingFeatures);
  bool GetHaloExtent(int& neighbors, int& levels) const override
  {
    neighbors = levels = 0;
    return false;
  }
};

// Every point array of `b` equals `a`'s, bit for bit; the field data's figures too.
bool Same(vtkPolyData* a, vtkPolyData* b, const std::string& label)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    std::printf("%s: %lld points, one process %lld\n", label.c_str(),
      static_cast<long long>(b->GetNumberOfPoints()),
      static_cast<long long>(a->GetNumberOfPoints()));
    return false;
  }
  bool same = true;
  for (int i = 0; i < a->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* x = a->GetPointData()->GetArray(i);
    vtkDataArray* y = x ? b->GetPointData()->GetArray(x->GetName()) : nullptr;
    if (!x)
    {
      continue;
    }
    if (!y || y->GetDataType() != x->GetDataType() ||
      y->GetNumberOfComponents() != x->GetNumberOfComponents())
    {
      std::printf("%s: array %s missing or of another type\n", label.c_str(), x->GetName());
      same = false;
      continue;
    }
    const size_t bytes = static_cast<size_t>(x->GetDataTypeSize()) * x->GetNumberOfComponents();
    vtkIdType differ = 0, first = -1;
    for (vtkIdType t = 0; t < x->GetNumberOfTuples(); ++t)
    {
      if (std::memcmp(static_cast<char*>(x->GetVoidPointer(0)) + bytes * t,
            static_cast<char*>(y->GetVoidPointer(0)) + bytes * t, bytes) != 0)
      {
        first = first < 0 ? t : first;
        ++differ;
      }
    }
    if (differ)
    {
      std::printf("%s: array %s differs at %lld points (first %lld: %.9g, one process %.9g)\n",
        label.c_str(), x->GetName(), static_cast<long long>(differ), static_cast<long long>(first),
        y->GetComponent(first, 0), x->GetComponent(first, 0));
      same = false;
    }
  }
  for (const char* name : { "MeanSpacing", "FeatureThreshold" })
  {
    vtkDataArray* x = a->GetFieldData()->GetArray(name);
    vtkDataArray* y = b->GetFieldData()->GetArray(name);
    if (!x || !y || x->GetTuple1(0) != y->GetTuple1(0))
    {
      std::printf("%s: field %s differs (%.17g, one process %.17g)\n", label.c_str(), name,
        y ? y->GetTuple1(0) : -1.0, x ? x->GetTuple1(0) : -1.0);
      same = false;
    }
  }
  return same;
}
} // namespace

// --compare-pvtp: see the file's comment.
int ComparePieces(const char* pvtp, const char* referenceFile, int pieces)
{
#ifndef FEATUREPOINTS_TEST_PVTP
  std::printf("%s: this build has no VTK::IOParallelXML to read it with\n", pvtp);
  (void)referenceFile;
  (void)pieces;
  return EXIT_FAILURE;
#else
  std::string error;
  vtkSmartPointer<vtkPointSet> reference = vtkPointCloudIO::Read(referenceFile, error);
  if (!reference)
  {
    std::printf("%s\n", error.c_str());
    return EXIT_FAILURE;
  }
  vtkNew<vtkXMLPPolyDataReader> reader;
  reader->SetFileName(pvtp);
  reader->UpdateInformation();
  if (reader->GetNumberOfPieces() != pieces)
  {
    std::printf("%s: %d pieces, %d expected\n", pvtp, reader->GetNumberOfPieces(), pieces);
    return EXIT_FAILURE;
  }
  const vtkIdType n = reference->GetNumberOfPoints();
  std::vector<int> seen(n, 0);
  int failed = 0;
  for (int p = 0; p < pieces; ++p)
  {
    reader->UpdatePiece(p, pieces, 0);
    vtkPolyData* piece = reader->GetOutput();
    vtkDataArray* gids = piece->GetPointData()->GetArray("GlobalPointIds");
    if (!gids)
    {
      std::printf("piece %d: no GlobalPointIds\n", p);
      return EXIT_FAILURE;
    }
    long long last = -1;
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      const long long g = static_cast<long long>(gids->GetTuple1(i));
      if (g <= last || g >= n)
      {
        std::printf("piece %d: point %lld has GlobalPointIds %lld after %lld\n", p,
          static_cast<long long>(i), g, last);
        return EXIT_FAILURE;
      }
      last = g;
      ++seen[g];
      double x[3], y[3];
      piece->GetPoint(i, x);
      reference->GetPoint(g, y);
      bool same = x[0] == y[0] && x[1] == y[1] && x[2] == y[2];
      for (int a = 0; a < reference->GetPointData()->GetNumberOfArrays(); ++a)
      {
        vtkDataArray* r = reference->GetPointData()->GetArray(a);
        vtkDataArray* q = r ? piece->GetPointData()->GetArray(r->GetName()) : nullptr;
        for (int c = 0; r && q && c < r->GetNumberOfComponents(); ++c)
        {
          same = same && r->GetComponent(g, c) == q->GetComponent(i, c);
        }
        same = same && (!r || q);
      }
      if (!same && failed++ < 5)
      {
        std::printf("piece %d: point %lld (global %lld) differs from one process's\n", p,
          static_cast<long long>(i), g);
      }
    }
    std::printf("piece %d: %lld points, global ids ascending\n", p,
      static_cast<long long>(piece->GetNumberOfPoints()));
  }
  const vtkIdType once = std::count(seen.begin(), seen.end(), 1);
  if (once != n)
  {
    std::printf("%lld of %lld points are in exactly one piece\n", static_cast<long long>(once),
      static_cast<long long>(n));
    return EXIT_FAILURE;
  }
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
#endif
}

int main(int argc, char* argv[])
{
  if (argc == 5 && std::string(argv[1]) == "--compare-pvtp")
  {
    return ComparePieces(argv[2], argv[3], std::atoi(argv[4]));
  }
  const std::string mode = argc == 4 ? argv[1] : "";
  if (mode == "--write" || mode == "--write-plain" || mode == "--write-plate")
  {
    std::string error;
    vtkSmartPointer<vtkPolyData> cloud = mode == "--write-plate"
      ? WithDuplicates(Bracket(std::atoll(argv[3]), vtkFeatureModelSource::PLATE_WITH_HOLE), 16)
      : Bracket(std::atoll(argv[3]));
    if (mode == "--write")
    {
      cloud = WithDuplicates(cloud);
    }
    if (!vtkPointCloudIO::Write(cloud, argv[2], error))
    {
      std::printf("%s\n", error.c_str());
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  }
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId();
  const int nProcs = controller->GetNumberOfProcesses();
  const int expected = argc > 1 ? std::atoi(argv[1]) : nProcs;
  int failed = nProcs == expected ? 0 : 1;
  if (failed && rank == 0)
  {
    std::printf("started with %d processes, %d expected\n", nProcs, expected);
  }

  vtkSmartPointer<vtkPolyData> bracket = Bracket(20000);
  vtkSmartPointer<vtkPolyData> duplicates = WithDuplicates(bracket);
  // The voxel pre-filter finds density contrast on the plate; at 90,000 points (65,536 or more)
  // after its quick screen on a sample.
  vtkSmartPointer<vtkPolyData> plate = Bracket(20000, vtkFeatureModelSource::PLATE_WITH_HOLE);
  vtkSmartPointer<vtkPolyData> plateDuplicates = WithDuplicates(plate, 16);
  vtkSmartPointer<vtkPolyData> large = Bracket(90000, vtkFeatureModelSource::PLATE_WITH_HOLE);
  // Noise of 1.5 spacings: the noise figure is measured again across the surface, from wider
  // searches of every row (own and halo).
  vtkSmartPointer<vtkPolyData> noisy = Bracket(20000, vtkFeatureModelSource::BRACKET, 1.5);
  struct Case
  {
    const char* Name;
    vtkPolyData* Cloud;
    std::function<vtkSmartPointer<vtkFeaturePointDetector>()> Make;
    bool Distributed; // the cloud is split (false: run on process 0 alone)
    bool Prefiltered; // the voxel pre-filter keeps some points only (not every point a candidate)
  };
  auto make = [](vtkFeaturePointDetector* detector) {
    vtkSmartPointer<vtkFeaturePointDetector> owned;
    owned.TakeReference(detector);
    return owned;
  };
  auto huang = [](bool voxels) {
    auto f = vtkSmartPointer<vtkFeaturePointExtraction>::New();
    f->SetUseVoxelFilter(voxels);
    return vtkSmartPointer<vtkFeaturePointDetector>(f);
  };
  const Case cases[] = {
    { "huang2023 (voxel filter off), bracket", bracket, [&] { return huang(false); }, true,
      false },
    { "huang2023 (voxel filter off), duplicates", duplicates, [&] { return huang(false); }, true,
      false },
    { "variation, bracket", bracket,
      [&] { return make(vtkSurfaceVariationFeatures::New()); }, true, false },
    { "curvature, duplicates", duplicates,
      [&] { return make(vtkCurvatureDensityFeatures::New()); }, true, false },
    { "huang2023 (defaults), bracket", bracket, [&] { return huang(true); }, true, false },
    { "huang2023 (defaults), plate", plate, [&] { return huang(true); }, true, true },
    { "huang2023 (defaults), plate with duplicates", plateDuplicates,
      [&] { return huang(true); }, true, true },
    { "huang2023 (defaults), plate 90000", large, [&] { return huang(true); }, true, true },
    { "crease (defaults), bracket", bracket,
      [&] { return make(vtkCreaseVotingFeatures::New()); }, true, false },
    // Distributed runs score copies as they are: the one-process run too (MergeCopies off).
    { "crease (copies kept), duplicates", duplicates,
      [&] {
        auto f = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
        f->MergeCopiesOff();
        return vtkSmartPointer<vtkFeaturePointDetector>(f);
      },
      true, false },
    { "crease (40 neighbours, thin, offsets, copies kept), duplicates", duplicates,
      [&] {
        auto f = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
        f->MergeCopiesOff();
        f->SetNumberOfNeighbors(40);
        f->ThinFeaturesOn();
        f->CreaseOffsetsOn();
        return vtkSmartPointer<vtkFeaturePointDetector>(f);
      },
      true, false },
    // Distributed runs keep the stray points that a one-process run leaves out (at this noise
    // a few points lie far enough off): the one-process run too.
    { "crease (outliers kept), bracket at sigma 1.5 s", noisy,
      [&] {
        auto f = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
        f->RemoveOutliersOff();
        return vtkSmartPointer<vtkFeaturePointDetector>(f);
      },
      true, false },
    { "crease (defaults), plate 90000", large,
      [&] { return make(vtkCreaseVotingFeatures::New()); }, true, false },
    { "crease declared not distributable, bracket", bracket,
      [&] { return make(OneProcessCrease::New()); }, false, false },
  };
  // FEATUREPOINTS_TEST_CASES: run only the cases whose name holds this text.
  const char* only = std::getenv("FEATUREPOINTS_TEST_CASES");
  for (const Case& c : cases)
  {
    if (only && !std::strstr(c.Name, only))
    {
      continue;
    }
    // One process on the whole cloud (process 0 only).
    vtkSmartPointer<vtkPolyData> reference;
    if (rank == 0)
    {
      auto single = c.Make();
      single->SetInputData(c.Cloud);
      single->Update();
      reference = single->GetOutput();
    }
    const auto start = std::chrono::steady_clock::now();
    auto detector = c.Make();
    vtkNew<vtkDistributedFeaturePoints> driver;
    driver->SetDetector(detector);
    driver->SetInputData(Piece(c.Cloud, rank, nProcs));
    driver->GatherOutputOn();
    driver->Update();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int ok = 1;
    if (rank == 0)
    {
      const std::string label = std::string(c.Name) + ", " + std::to_string(nProcs) + " ranks";
      ok = Same(reference, driver->GetOutput(), label) ? 1 : 0;
      if (driver->GetDistributed() != c.Distributed)
      {
        std::printf("%s: %s, expected %s\n", label.c_str(),
          driver->GetDistributed() ? "split" : "not split", c.Distributed ? "split" : "not split");
        ok = 0;
      }
      vtkIdType owned = 0, halo = 0;
      for (int r = 0; r < driver->GetNumberOfRanks(); ++r)
      {
        owned += driver->GetNumberOfOwnedPoints(r);
        halo += driver->GetNumberOfHaloPoints(r);
      }
      vtkDataArray* candidates = reference->GetPointData()->GetArray("Candidate");
      vtkIdType kept = 0;
      for (vtkIdType i = 0; candidates && i < candidates->GetNumberOfTuples(); ++i)
      {
        kept += candidates->GetTuple1(i) != 0.0 ? 1 : 0;
      }
      if (c.Prefiltered && !(kept > 0 && kept < reference->GetNumberOfPoints()))
      {
        std::printf("%s: %lld candidates of %lld points: the voxel pre-filter kept %s\n",
          label.c_str(), static_cast<long long>(kept),
          static_cast<long long>(reference->GetNumberOfPoints()), kept ? "every point" : "none");
        ok = 0;
      }
      if (owned != c.Cloud->GetNumberOfPoints() || (c.Distributed && halo == 0))
      {
        std::printf("%s: %lld own points (of %lld), %lld halo points\n", label.c_str(),
          static_cast<long long>(owned), static_cast<long long>(c.Cloud->GetNumberOfPoints()),
          static_cast<long long>(halo));
        ok = 0;
      }
      std::printf("%s: %s; %lld points, %lld feature points, halo %lld, %.2f s\n", label.c_str(),
        ok ? "identical to one process" : "MISMATCH",
        static_cast<long long>(c.Cloud->GetNumberOfPoints()),
        static_cast<long long>(detector->GetNumberOfFeaturePoints()), static_cast<long long>(halo),
        seconds);
    }
    controller->Broadcast(&ok, 1, 0);
    failed += ok ? 0 : 1;
  }
  controller->Finalize();
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
