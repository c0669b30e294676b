# The rig on Debian 12, built, with its scenarios (issue 37): what the
# suite examples of docs/SUITES.md run. scripts/setup.sh installs the same
# Debian packages as on a machine and builds into build/; ../shared (the
# specification texts) is not needed to build or run.
#   docker build -t hil-rig .
#   docker run --rm --network none --cap-add NET_ADMIN hil-rig \
#     scripts/in_netns.sh --here build/bin/hil run scenarios/demo.yaml
# scripts/container_check.sh builds and runs it from a clean clone (no
# registry needed: the base comes from debootstrap) and prints the times.
FROM debian:bookworm
ENV DEBIAN_FRONTEND=noninteractive
WORKDIR /hil
COPY . /hil
RUN HIL_BUILD_TARGETS="hil" scripts/setup.sh && rm -rf /var/lib/apt/lists/*
CMD ["build/bin/hil", "--help"]
