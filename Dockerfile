# ductile-contact on Debian bookworm: the packages of scripts/install-deps.sh,
# a Release build and the test suite. Build and test:
#   docker build -t ductile-contact .
# Run a scene (results in the mounted folder):
#   docker run --rm -v "$PWD/results:/ductile-contact/results" ductile-contact \
#     mpirun -np 2 ductile-contact prm/block_on_plate.prm
FROM debian:bookworm

ENV DEBIAN_FRONTEND=noninteractive \
    OMPI_ALLOW_RUN_AS_ROOT=1 \
    OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

WORKDIR /ductile-contact
COPY scripts/install-deps.sh scripts/
RUN apt-get update -q && apt-get install -y -q --no-install-recommends git \
    && scripts/install-deps.sh --plots \
    && rm -rf /var/lib/apt/lists/*

COPY . .
# The whole suite (about 10 minutes on 2 cores): the image is built only if
# it passes.
RUN scripts/test.sh
# The program on the PATH, the scenes in /usr/local/share/ductile-contact/prm.
RUN cmake --install build --prefix /usr/local
