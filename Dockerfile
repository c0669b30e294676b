# The rig on Debian 12, built, with its scenarios (issue 37): what the
# suite examples of docs/SUITES.md run. scripts/setup.sh installs the same
# Debian packages as on a machine and builds into build/; ../shared (the
# specification texts) is not needed to build or run.
#   docker build -t hil-rig .
#   docker run --rm --cap-add NET_ADMIN hil-rig sh -c 'scripts/in_netns.sh build/bin/hil run scenarios/ --in-process --jobs 2'
FROM debian:bookworm
ENV DEBIAN_FRONTEND=noninteractive
WORKDIR /hil
COPY . /hil
RUN HIL_BUILD_TARGETS="hil" scripts/setup.sh && rm -rf /var/lib/apt/lists/*
CMD ["build/bin/hil", "--help"]
