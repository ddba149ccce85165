// Shows the scene's own camera until the viewer page replaces this placeholder.
document.getElementById("view").src = "frame.png";
