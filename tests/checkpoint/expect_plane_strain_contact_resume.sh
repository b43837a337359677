#!/usr/bin/env bash
# Usage: expect_plane_strain_contact_resume.sh MPIEXEC EXECUTABLE SCENE.prm
#        END STEP2_END
# expect_plane_strain_resume.sh with a contact scene (prm/block_on_strip_2d.prm):
# see there.
exec "$(dirname "$0")/expect_plane_strain_resume.sh" "$@"
