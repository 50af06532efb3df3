ArtCam_file_for_2XAxisCNC
10 10
20 10 0,5
20 20
X0Y0
5 5
