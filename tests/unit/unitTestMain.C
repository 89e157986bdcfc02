/*---------------------------------------------------------------------------*\
  impactFoam unit tests (GoogleTest): main. OpenFOAM's FatalError and
  FatalIOError throw instead of exiting, so bad input can be tested.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "error.H"

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    return RUN_ALL_TESTS();
}
