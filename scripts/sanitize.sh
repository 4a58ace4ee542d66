#!/usr/bin/env bash
# Builds ringid with AddressSanitizer and UndefinedBehaviorSanitizer (no
# recovery, leaks detected) into build-asan/ and runs the test suite there,
# but for the long tests named below. Any finding fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
# Debian's Ceres is a static library built without sanitizers. Eigen drops its
# "glibc malloc is aligned" assumption under ASan, so without this define our
# objects and Ceres' copies of Eigen's inline allocator disagree (a bad free in
# BDCSVD inside ceres::Covariance). glibc and ASan both align malloc to 16.
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1 -DEIGEN_MALLOC_ALREADY_ALIGNED=1"
# The Python module is left out here: an ASan-built extension cannot load into
# Debian's uninstrumented python3 (the ASan runtime must come first); its
# tests run in the optimised suite.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRINGID_BUILD_BENCHMARKS=OFF \
  -DRINGID_BUILD_PYTHON=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" > /dev/null
cmake --build build-asan -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The long tests (8 s or more in the optimised suite, ctest -j2, when the
# list was made; ten times that under the sanitizers) are left to it, for
# CI's time. Whole names, so that a new test is never left out by a prefix:
# each repeats, over more
# starts, effects or profile steps, paths a shorter test below runs once
# (diagnose: NamesLugCouplingAndShrinksTheGap, ThePapersData; identifiability:
# ReportTest.IdentifiabilityRoundTripsByteForByte and the Table 1 tests;
# campaigns: CliTest.AnInterruptedCampaignNamesTheReportsItKept; every page
# kind but three in Chromium).
long=(
  QuickValidationSuiteFromScatteredStarts
  AnEffectTheDataCannotRejectAgainstTheVerdict
  ABaselineWithTheWithheldEffectLeavesNoGap
  TheStatedDetectableSizeOfTheHubHolds
  AnAbsorbableEffectIsNoneWithItsDetectableSize
  DiagnoseTest.NoEffectNoAlarm
  DiagnoseTest.NamesASoftHub
  EffectFreeRollingDataRaiseNoAlarm
  AFailedRefitIsRetriedAndOnlyARealJumpIsSaid
  ProfileBoundsAreRefittedCrossingsAndJumpsAreSaidApart
  Format2DatasetThroughIdentifiabilityCompareAndReport
  DiagnosisDoesNotDependOnJobs
  ShardsPartitionTheDatasetsAndReproduceTheirReports
  DiagnoseAndCampaignRoundTripByteForByte
  CampaignOfDiagnosesDrawsTheGaps
  IdentifiabilityDrawsSpectrumCorrelationAndProfiles
  IdentifiabilitySaysAJumpBesideTheBound
  'PageRendersWithEveryFigureWhole/(identifiability|campaign|diagnose|extract|extract_drum)( |$)'
  # 60-120 s each under the sanitizers (2026-11-27), beside a shorter test of
  # the same path: RollingTest.LabelsCarriedFromAnAnchor..., CampaignResumeTest's
  # other tests (and CI's campaign benchmark), DiagnoseTest.NamesLugCoupling...,
  # the static_measurement tests.
  RollingTest.LabelsAtScatteredPointsAreThoseOfTheReferenceContinuation
  CampaignResumeTest.AKilledShardRefitsOnlyWhatItHadNotFinishedAndTheMergeIsTheSerialTable
  DiagnoseTest.TheReportIsTheSameOnOneThreadAndOnSeveral
  SuitesTest.StaticStiffnessesAndModesIdentifyScatteredTiresFromScatteredStarts
  # A noise-free FRF fit (0.5 s optimised): the noisy one beside it runs the same paths.
  FrfMeasurementTest.ANoiseFreeHammerTestGivesTheTruthWithTheMassesFree
  # FRF fits of six starts, each through the modal stage (1-2 s optimised):
  # FrfStartTest's extraction test and the fits of frf_measurement_test run its paths.
  FrfStartTest.FromInitialValuesScatteredByAFactorThreeTheBestFitIsFound
  FrfStartTest.ShapelessModesAreLabelledByTheFrfsSoTheStartsAgree
  # Diagnoses of FRFs (1.4 and 2.4 s of CPU optimised): AbsorbedBy and BaselineFrom
  # run under the sanitizers in AnAbsorptionIsSaidOnlyWhereTheDataConfirmIt and
  # ABaselineStartFromAnAbsorbedSensorMassMovesItIntoTheMasses (0.1 s each).
  DiagnoseTest.OnFrfsTheFreeMassesAbsorbASensorMassAndTheReportSaysSo
  DiagnoseTest.OnFrfsALugCouplingIsNamedAboveItsStatedDetectableSizeAndNotBelow
  # extract fits the FRFs to name the modes (six starts through the modal stage, 1-3 s
  # optimised): ExtractTest.TheReportAndTheDatasetAreWrittenTogetherOrNotAtAll runs the
  # command's paths, and extract_page.cc's under ASan only here (its figures' code is
  # identify's FRF section, which the identify_frf pages run).
  ExtractTest.TheTwoRoutesAgreeWithinTheirIntervalsAndTheDirectOnesAreNarrower
  ExtractTest.ExtractThenIdentifyWithTheMassesWeighedRecoversTheTruth
  ExtractTest.NoiseFreeFrfsGiveTheModelsModesLabelledAsTheModelLabelsThem
  ExtractTest.AParameterSetsMassesAreTheOnesTheModalDatasetHolds
  ExtractTest.TheReportOfNoiseFreeFrfsSynthesisesEachFunctionAndItsDiagramHoldsTheModes
  # A drum's extraction through the fit that names its modes (3.6 s optimised): the blocks and
  # real poles run under the sanitizers in PlscfTest.ADrumsFrfsAtSpeedGiveTheModelsPolesAtThatSpeed.
  ExtractTest.ADrumsFrfsAtSpeedGiveTheModelsModesAtThatSpeedLabelledAsTheModelLabelsThem
  HtmlReportTest.ExtractDrawsTheDiagramAndEachFunctionAgainstItsSynthesis
  HtmlReportTest.ExtractAtSpeedDrawsADiagramPerBlock
  ReportTest.ExtractRoundTripsByteForByteAndIsDocumented
  # 100 refinements (2-3 s optimised); the noise-free refinement test runs its paths.
  ModalRefineTest.TheStandardErrorsOfTwoCloseDampedModesCoverTheTruth
)
cd build-asan && ctest --output-on-failure -j"$(nproc)" -E "$(IFS='|'; echo "${long[*]}")"
