// rocksweep: overturning spectra of rocking blocks, free-standing or anchored.
#include <exception>
#include <iostream>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/parallel/mpi_session.hpp"

int main(int argc, char** argv) {
    rocksweep::MpiSession mpi(argc, argv);
    try {
        return rocksweep::run_cli(argc, argv, mpi);
    } catch (const std::exception& e) {
        // Past parsing, an error may be local to this rank while the others wait on it.
        if (mpi.size() > 1) rocksweep::abort_on_error(mpi.rank(), e);
        std::cerr << "rocksweep: error: " << e.what() << '\n';
        return 1;
    }
}
