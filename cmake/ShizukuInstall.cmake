# What `cmake --install build --prefix P` puts besides the programs (whose rules
# are in solver/ and utilities/: P/bin):
#   P/share/shizuku/tutorials   the tutorial cases, without anything a run wrote
#   P/share/shizuku/etc         bashrc (the environment) and tutorialFunctions (Allrun helpers)
#   P/share/doc/shizuku         README.md and docs/ (README's links stay relative)
# An installed case finds its programs as a repository case does: its Allrun
# sources $SHIZUKU_DIR/etc/tutorialFunctions, SHIZUKU_DIR being P/share/shizuku.
set(SHIZUKU_DATA_DIR share/shizuku)
set(SHIZUKU_DOC_DIR share/doc/shizuku)

# Outputs of a run in the source tutorials (.gitignore): time folders, logs,
# postProcessing/, plots/, particles.pvd, temporary files of an interrupted write.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tutorials/ DESTINATION ${SHIZUKU_DATA_DIR}/tutorials
        USE_SOURCE_PERMISSIONS
        REGEX "/[0-9][^/]*$" EXCLUDE
        REGEX "/(postProcessing|plots|__pycache__)$" EXCLUDE
        REGEX "/(log\\.[^/]*|particles\\.pvd|[^/]*\\.tmp-[^/]*|[^/]*\\.pyc)$" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/etc/bashrc ${PROJECT_SOURCE_DIR}/etc/tutorialFunctions
        DESTINATION ${SHIZUKU_DATA_DIR}/etc)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${SHIZUKU_DOC_DIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${SHIZUKU_DOC_DIR}/docs)
